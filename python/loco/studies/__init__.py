"""Parameter studies of SPEC §6, each usable on its own.

- :mod:`loco.studies.parameters`: the six study parameters, their ranges, SI conversion.
- :mod:`loco.studies.sampling`: Latin hypercube and Saltelli designs.
- :mod:`loco.studies.evaluators`: the ``evaluate(params, names) -> metrics`` protocol every study
  takes, and the simulator evaluator (``loco.run_batch``).
- :mod:`loco.studies.sensitivity`: Sobol' indices, direct and on a surrogate; convergence.
- :mod:`loco.studies.surrogate`: the RBF neural network, cross-validated R², parity plot.
- :mod:`loco.studies.optimisation`: NSGA-II Pareto front, spread of points, re-simulation.
- :mod:`loco.studies.report`: study records, CSV/JSON output, the Markdown report.
- :mod:`loco.studies.stages`: resumable stages (skipped when finished with the same settings).

The submodules are imported on demand (``from loco.studies import sensitivity``): SALib, pymoo and
scikit-learn load only when a study needs them.
"""

__all__ = [
    "evaluators",
    "optimisation",
    "parameters",
    "report",
    "sampling",
    "sensitivity",
    "stages",
    "surrogate",
]
