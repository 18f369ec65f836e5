"""Simulator coefficients: simulators' simple rotor models fitted to propmap, hover pinned,
with their error against the full model (forms.py: the models; fit.py: the fit; files.py:
each target's file and the report)."""

from .files import check_rotorpy_vehicle, error_lines, report_path, rotorpy_directions, write_export
from .fit import Envelope, SimExport, default_envelope, export_sim
from .forms import ALIASES, TARGETS, canonical_target, predict

__all__ = ["ALIASES", "Envelope", "SimExport", "TARGETS", "canonical_target", "check_rotorpy_vehicle",
           "default_envelope", "error_lines", "export_sim", "predict", "report_path", "rotorpy_directions",
           "write_export"]
