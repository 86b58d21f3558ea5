"""The study of SPEC §6 as stages of ``loco reproduce`` (:mod:`loco.studies.reproduce`), and
the methods they share, each usable on its own.

Each stage (a frozen dataclass of its inputs, :mod:`loco.studies.stages`) and the module it
lives in, with the modules only it uses:

- ``speed_sweep``: :mod:`~loco.studies.speed_sweep` (W_y and A_yb against speed, PSDs at
  200 km/h, §6.1), figures in :mod:`~loco.studies.speed_sweep_figures`.
- ``monte_carlo``: :mod:`~loco.studies.monte_carlo` (the Latin hypercube Monte Carlo, §6.2),
  with :mod:`~loco.studies.parameter_study` (the objectives and the samples' table, which the
  surrogate stages share).
- ``surrogate_samples``, ``surrogate_holdout``: :mod:`~loco.studies.surrogate_samples`,
  :mod:`~loco.studies.surrogate_holdout` (the samples the surrogates learn from and are scored on).
- ``surrogate``: :mod:`~loco.studies.surrogate` (R² and the surrogate used, §6.3),
  with :mod:`~loco.studies.rbf_network` (the RBF network), :mod:`~loco.studies.surrogate_reference`
  and :mod:`~loco.studies.gp_kernel` (the Gaussian processes), :mod:`~loco.studies.
  surrogate_selection` and :mod:`~loco.studies.surrogate_fits` (the choice by cross-validation).
- ``sensitivity``: :mod:`~loco.studies.sensitivity` (Sobol' indices, §6.2), with
  :mod:`~loco.studies.sobol` (the indices, their intervals and figures).
- ``optimisation``: :mod:`~loco.studies.optimisation` (NSGA-II on the surrogates, §6.4), with
  :mod:`~loco.studies.pareto` (the search and the front).
- ``damper_bench``: :mod:`~loco.studies.damper_bench` (§6.5), with
  :mod:`~loco.studies.valve_bench` (the FSD's frequency valve).
- ``fsd_comparison``: :mod:`~loco.studies.fsd_comparison` (YD1, YD2, FSD and FSD-H on S_low and
  S_high, §6.6), its runs and tables in :mod:`~loco.studies.fsd_tables`, figures in
  :mod:`~loco.studies.fsd_figures`.
- ``fsd_design``: :mod:`~loco.studies.fsd_design`, with :mod:`~loco.studies.fsd_search`
  (NSGA-II on the simulator) and :mod:`~loco.studies.fsd_conicity` (the conicity sweep).
- ``premise_case``: :mod:`~loco.studies.premise_case` (the comparison where the premise holds).
- ``premise_map``: :mod:`~loco.studies.premise_map`, with :mod:`~loco.studies.premise_modes`
  (the linearised modes over conicity, yaw damping and speed).
- ``screening``: :mod:`~loco.studies.screening` (Morris screening of the ranged inputs).
- ``plausible``: :mod:`~loco.studies.plausible`, with :mod:`~loco.studies.premise_probability`
  (plausible locomotives and the premise rule). :mod:`~loco.studies.premise_study` runs these
  three stages on any vehicle file.
- ``curving`` (``--full``): :mod:`~loco.studies.curving`, its curves and sizes in
  :mod:`~loco.studies.curving_cases`, figures in :mod:`~loco.studies.curving_figures`, EN 14363
  processing in :mod:`~loco.studies.en14363`.

Shared by the stages:

- :mod:`~loco.studies.reproduce`: the stages in order and the report; :mod:`~loco.studies.sizes`:
  the presets' sizes.
- :mod:`~loco.studies.quantities`: the scenarios, channels and metrics of W_y, A_yb and A_yc,
  named once.
- :mod:`~loco.studies.parameters`: the six study parameters, their ranges, SI conversion.
- :mod:`~loco.studies.sampling`: Latin hypercube and Saltelli designs.
- :mod:`~loco.studies.evaluators`: the ``evaluate(params, names) -> metrics`` protocol every study
  takes, and the simulator evaluator (``loco.run_batch``).
- :mod:`~loco.studies.seeds`: one case on several synthesised tracks (one batch, tracks as
  samples); :mod:`~loco.studies.statistics`: geometric means, intervals, paired tests, rankings.
- :mod:`~loco.studies.stages`: a stage as a frozen dataclass of its inputs, hashed from them, and
  the runner that skips a stage finished with the same inputs.
- :mod:`~loco.studies.report`, :mod:`~loco.studies.report_html`: study records, CSV/JSON
  output, the Markdown report and the HTML page; :mod:`~loco.studies.captions`: what to read
  from each figure; :mod:`~loco.studies.plotting`: the figures' shared set-up.
- :mod:`~loco.studies.verdict`: which yaw damper holds which scenario;
  :mod:`~loco.studies.premise_report`: "Does the premise hold?".

The submodules are imported on demand (``from loco.studies import sobol``): SALib, pymoo and
scikit-learn load only when a study needs them.
"""

__all__ = [
    "captions",
    "curving",
    "curving_cases",
    "curving_figures",
    "damper_bench",
    "en14363",
    "evaluators",
    "fsd_comparison",
    "fsd_conicity",
    "fsd_design",
    "fsd_figures",
    "fsd_search",
    "fsd_tables",
    "gp_kernel",
    "monte_carlo",
    "optimisation",
    "parameter_study",
    "parameters",
    "pareto",
    "plausible",
    "plotting",
    "premise_case",
    "premise_map",
    "premise_modes",
    "premise_probability",
    "premise_report",
    "premise_study",
    "quantities",
    "rbf_network",
    "report",
    "report_html",
    "reproduce",
    "sampling",
    "screening",
    "seeds",
    "sensitivity",
    "sizes",
    "sobol",
    "speed_sweep",
    "speed_sweep_figures",
    "stages",
    "statistics",
    "surrogate",
    "surrogate_fits",
    "surrogate_holdout",
    "surrogate_reference",
    "surrogate_samples",
    "surrogate_selection",
    "valve_bench",
    "verdict",
]
