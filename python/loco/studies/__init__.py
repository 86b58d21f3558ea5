"""Parameter studies of SPEC §6, each usable on its own.

- :mod:`loco.studies.parameters`: the six study parameters, their ranges, SI conversion.
- :mod:`loco.studies.sampling`: Latin hypercube and Saltelli designs.
- :mod:`loco.studies.evaluators`: the ``evaluate(params, names) -> metrics`` protocol every study
  takes, and the simulator evaluator (``loco.run_batch``).
- :mod:`loco.studies.sensitivity`: Sobol' indices, direct and on a surrogate; convergence.
- :mod:`loco.studies.surrogate`: the RBF neural network, cross-validated R², parity plot;
  :mod:`loco.studies.surrogate_reference`: the Gaussian process; :mod:`loco.studies.
  surrogate_selection`: the surrogate the optimisation uses, chosen by cross-validation.
- :mod:`loco.studies.seeds`: one case on several synthesised tracks (one batch, tracks as
  samples); :mod:`loco.studies.statistics`: means, 95 % intervals, paired tests, rankings.
- :mod:`loco.studies.optimisation`: NSGA-II Pareto front, spread of points, re-simulation.
- :mod:`loco.studies.report`: study records, CSV/JSON output, the Markdown report.
- :mod:`loco.studies.stages`: a stage as a frozen dataclass of its inputs, hashed from them, and
  the runner that skips a stage finished with the same inputs.

The studies of SPEC §6, each writing its figures, tables and report record:

- :mod:`loco.studies.speed_sweep`: W_y and A_yb against speed, PSDs at 200 km/h (§6.1); its
  figures in :mod:`loco.studies.speed_sweep_figures`.
- :mod:`loco.studies.parameter_study`: objectives, Latin hypercube Monte Carlo (§6.2);
  :mod:`loco.studies.surrogate_validation`: surrogate R² and the surrogate used (§6.3);
  :mod:`loco.studies.parameter_stages`: Sobol' indices and NSGA-II (§6.2, §6.4).
- :mod:`loco.studies.fsd_comparison`: YD1, YD2 and FSD on S_low and S_high (§6.6); its
  figures in :mod:`loco.studies.fsd_figures`.

``loco reproduce`` (:mod:`loco.commands.reproduce`) runs them all.

The submodules are imported on demand (``from loco.studies import sensitivity``): SALib, pymoo and
scikit-learn load only when a study needs them.
"""

__all__ = [
    "evaluators",
    "fsd_comparison",
    "fsd_figures",
    "optimisation",
    "parameter_stages",
    "parameter_study",
    "parameters",
    "report",
    "sampling",
    "seeds",
    "sensitivity",
    "speed_sweep",
    "speed_sweep_figures",
    "stages",
    "statistics",
    "surrogate",
    "surrogate_reference",
    "surrogate_selection",
    "surrogate_validation",
]
