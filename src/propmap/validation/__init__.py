"""The model against measurements: per run, and cross-validated over the catalogue.

* :func:`validate` (runs.py): the model (either section model) and the hover model
  T = k_T Omega^2, calibrated on the MEASURED static CT and CP (mean over the static runs),
  against a catalogue propeller's UIUC static runs and J-sweeps, as in Fig. 7 of Gill &
  D'Andrea (2017).
* :func:`cross_validate` (catalogue.py): held-out errors of the calibration protocols (leave one sweep
  out, static-only calibration, static + lowest-rpm sweep, blind prediction with a generic
  set that never saw the propeller), in the metric rms |dCT| / static CT and
  |dCP| / static CP.
* :func:`holdout_loads` (loads.py): held-out errors of fits to load data at incidence (thrust, in-plane
  force, torque), each fold's training points fitted with the defaults or given names.
* :func:`load_errors` (loads.py): a parameter set against a user's own load data (a thrust stand's, a
  wind tunnel's), overall and per group (``propmap validate DATA --prop GEOM``).

Measurements: UIUC Propeller Data Site vol. 1 (Brandt & Selig, AIAA 2011-1255).
"""

from .catalogue import PROTOCOL_TEXT, PROTOCOLS, coefficient_errors, cross_validate, rpm_groups
from .loads import holdout_loads, load_errors
from .runs import SweepComparison, Validation, holdout_comparison, validate

__all__ = ["PROTOCOLS", "PROTOCOL_TEXT", "SweepComparison", "Validation", "coefficient_errors", "cross_validate",
           "holdout_comparison", "holdout_loads", "load_errors", "rpm_groups", "validate"]
