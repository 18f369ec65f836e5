"""The model's own uncertainty, stated beside the errors of maps and exports against it.

A map's interpolation error and an export's fit error are measured against propmap itself.
What a user also needs is how far propmap is from measurements with the parameter set in
use. propmap knows that axially, from cross-validation on the bundled UIUC catalogue
(docs/validation.md), and says in words what it does not know off-axis.

The figures are rms |dCT| / static CT (and |dCP| / static CP) over each propeller's held-out
sweeps: median / 90th percentile / worst over the 143 catalogue propellers of UIUC vol. 1
(Brandt & Selig, AIAA 2011-1255) and vol. 2 (Deters, Ananda & Selig, AIAA 2014-2151), with
defaults derived without each propeller's family (leave-one-family-out). Measured
2026-11-24 (the calibration with the stall blend M = 12) by ``propmap validate --all``, and
the same figures again on 2026-11-29 and 2026-11-30 (the calibration of 2026-11-29);
tests/test_uncertainty.py holds them to docs/validation.md.
"""

from __future__ import annotations

from pathlib import Path

from .nominal_geometry import NOMINAL_COST, NOMINAL_SOURCE

__all__ = ["AXIAL_VALIDATION", "OFF_AXIS", "model_uncertainty"]

#: cross-validated axial errors by kind of parameter set: (median, 90th percentile, worst)
AXIAL_VALIDATION = {
    "calibrated": {"protocol": "leave one sweep out (the set fitted to the propeller's other sweeps)",
                   "ct": (0.025, 0.049, 0.110), "cp": (0.028, 0.043, 0.130)},
    "generic": {"protocol": "blind (the generic set derived without the propeller's family)",
                "ct": (0.076, 0.192, 0.431)},
    "paper": {"protocol": "the paper's Table I without a fit", "ct": (0.213, 0.332, 0.492)},
}
#: what is known off-axis, in words (docs/validation.md, docs/flight.md)
OFF_AXIS = ("not validated at incidence for this propeller: the UIUC data behind the shipped sets are axial. "
            "propmap's off-axis checks are the Beaver propeller at 0-20 deg (Sinnige et al. 2019: the generic "
            "set's rise of the wind-axis thrust with incidence is about a fifth of the measured one, and 61-82% of "
            "it with the zero-incidence thrust matched by one collective offset), the NeuroBEM quadrotor's flight "
            "logs (Bauersfeld et al. 2021: the vehicle model with a fitted airframe predicts held-out body force to "
            "0.298 N rms, docs/flight.md, but the logs do not separate the rotors' in-plane force from the "
            "airframe's) and four catalogue propellers in oblique flow (Gill & D'Andrea 2019: with their own sets "
            "the in-plane force rises with the advance ratio at 0.47-0.73 of the measured rate, and the edgewise "
            "thrust of the three APC electric ones by 4-9% where the measured rises by 15-19% at mu = 0.2, and "
            "their rigid blades' rolling moment at 1.17-1.77 times the measured one); off-axis loads rest on the "
            "BET/BEMT physics (docs/validation.md)")


def _pct(t) -> str:
    return " / ".join(f"{100 * v:.1f}" for v in t) + "%"


def model_uncertainty(label: str, propeller=None) -> dict:
    """What propmap knows of its own error against measurements with a parameter set.

    Parameters
    ----------
    label : str
        The set's label as outputs record it: ``"calibrated:NAME"``, ``"generic"`` (or a
        generic fold), ``"gill2017-*"`` (the paper's Table I), ``"section:NAME"``, a
        parameter file's path, or anything else (unknown).
    propeller : Propeller, optional
        The propeller modelled: a nominal blade (built from a size designation,
        :mod:`propmap.io.nominal_geometry`) adds what such a blade cost on the catalogue to
        ``axial``, whose figures are for measured blades.

    Returns
    -------
    dict
        ``params`` (the label); ``axial``: a sentence with the cross-validated CT (and CP)
        error median / 90th percentile / worst over the catalogue, or why there is none;
        ``axial_ct`` (and ``axial_cp``): the three fractions, absent where unknown;
        ``in_sample_rms_ct`` for a catalogue propeller's own set; ``off_axis``: a sentence.
    """
    label = str(label)
    out: dict = {"params": label}
    kind = ("calibrated" if label.startswith("calibrated:") else
            "generic" if label == "generic" or label.startswith("generic ") else
            "paper" if label.startswith("gill2017") else None)
    if kind is not None:
        v = AXIAL_VALIDATION[kind]
        out["axial_ct"] = list(v["ct"])
        text = (f"cross-validated over the UIUC catalogue (143 propellers, {v['protocol']}): rms CT error "
                f"{_pct(v['ct'])} of static CT (median / 90th percentile / worst)")
        if "cp" in v:
            out["axial_cp"] = list(v["cp"])
            text += f", CP {_pct(v['cp'])}"
        out["axial"] = text
        if kind == "calibrated":
            from .calibration import calibrated

            c = calibrated(label.split(":", 1)[1])
            if c is not None:
                out["in_sample_rms_ct"] = c.rms_ct
                out["axial"] += f"; this set's in-sample rms CT error {100 * c.rms_ct:.1f}%"
    elif label.startswith("section:"):
        out["axial"] = ("not validated on propellers: a symmetric rotor section's published polar (docs/models.md), "
                        "for rotor-like blades")
    elif label and Path(label).suffix.lower() == ".toml":
        out["axial"] = "a parameter file: its own fit report states its errors; propmap has no cross-validated figure"
    else:
        out["axial"] = "unknown: propmap has no validation figure for this parameter set"
    if propeller is not None and getattr(propeller, "source", "") == NOMINAL_SOURCE:
        out["axial"] += ("; those figures are for measured blades, and this propeller is a nominal blade (its size "
                         "only: docs/cli.md), whose CT error in % of static CT on the catalogue was, median UIUC "
                         f"vol. 1 / vol. 2, {NOMINAL_COST}")
    out["off_axis"] = OFF_AXIS
    if label and Path(label).suffix.lower() == ".toml":
        from .params_file import set_coverage

        try:
            cov = set_coverage(label) or {}
        except (OSError, ValueError):  # (an unreadable file: its reader says why where it is read)
            cov = {}
        # (a flight fit's incidences are its rotors' in flight, near 180 deg in any sink: not load data at incidence)
        top = float(cov.get("incidence_deg_max", 0.0)) if cov.get("data") != "flight logs" else 0.0
        if top > 0.0:  # a fit to load data at incidence (a map's sidecar called it 'not validated at incidence')
            out["off_axis"] = (f"fitted to load data at incidence up to {top:g} deg (the file's [coverage]); its "
                               "fit report states its errors there, held-out ones where groups were held out; "
                               "beyond that range: " + OFF_AXIS)
    return out
