"""A nominal blade for a propeller known only by its size: diameter, pitch and blade count.

Most users' propellers (a thrust-stand test of a racing or multirotor propeller, a
simulator's rotor) come without a measured blade geometry, only with the maker's size
designation ``D x P`` in inches. :func:`nominal_propeller` builds a blade for them:

* the chord is the median c/R, station by station, of the catalogue's blade geometries
  (:data:`CHORD_OVER_R` at :data:`R_OVER_R`): UIUC Propeller Data Site vol. 1 and 2 geometry
  files (Brandt & Selig, AIAA 2011-1255; Deters, Ananda & Selig, AIAA 2014-2151) and APC's
  PE0 files (APC Propellers, "Technical Information", v2022-0915), 147 propellers of 1.8-19
  in (``tools/nominal_geometry.py shape``; the catalogue's hubs put the first station at a
  median r/R of 0.15);
* the blade angle is the helix of the nominal pitch, theta = atan(P / (2 pi r)): the geometric
  pitch of a blade whose every station advances P per turn. Against the catalogue's measured
  blades, the measured angle at 0.75 R less the helix of the pitch in the name is -5.2 to +2.4
  deg (family medians; the APC electric, sport and slow-flyer families +0.2, +1.1 and -0.8
  deg), which is what makes a name a usable geometry.

How well such a blade predicts, blind and fitted, against the same propellers' own geometry,
is measured in docs/validation.md (A propeller known only by its size).
"""

from __future__ import annotations

import math
import re

import numpy as np

from ..core.geometry import INCH, Propeller

__all__ = ["R_OVER_R", "CHORD_OVER_R", "NOMINAL_SOURCE", "NOMINAL_COST", "DESIGNATION_MAX_IN", "nominal_propeller",
           "parse_size", "propeller_from_size"]

#: stations of the nominal blade [r/R]
R_OVER_R = (0.15, 0.20, 0.25, 0.30, 0.35, 0.40, 0.45, 0.50, 0.55, 0.60, 0.65, 0.70, 0.75, 0.80, 0.85, 0.90, 0.95,
            1.00)
#: median c/R of the catalogue's 147 blade geometries at :data:`R_OVER_R` (each geometry interpolated linearly
#: between its stations; UIUC vol. 1 and 2 geometry files and APC PE0 files; ``tools/nominal_geometry.py shape``,
#: 2026-12-02)
CHORD_OVER_R = (0.154, 0.150, 0.161, 0.171, 0.179, 0.180, 0.180, 0.179, 0.177, 0.172, 0.170, 0.164, 0.154, 0.140,
                0.124, 0.105, 0.080, 0.038)
NOMINAL_SOURCE = ("nominal blade: the helix of the named pitch on the median chord of the UIUC Propeller Data Site "
                  "vol. 1 and 2 and APC PE0 geometries (propmap.io.nominal_geometry)")

#: the largest diameter a size designation may give [in]: the catalogue's blades, whose median chord the nominal
#: blade takes, are 1.8-19 in; a designation beyond this is more likely in millimetres (``100x80``) than inches
DESIGNATION_MAX_IN = 40.0
#: a size designation ``D x P`` in inches, with an optional third figure, the blade count (``5x4.5x3``)
_SIZE_RE = re.compile(r"\s*(?P<D>\d+(?:\.\d+)?)\s*[xX]\s*(?P<P>\d+(?:\.\d+)?)(?:\s*[xX]\s*(?P<B>\d+))?\s*",
                      re.ASCII)


def parse_size(spec: str) -> tuple[float, float, int | None] | None:
    """The diameter, pitch [in] and blade count of a size designation, or None.

    Parameters
    ----------
    spec : str
        ``"DxP"`` or ``"DxPxB"``, D and P in inches (decimals with a point), B the blade count:
        ``"9x4.5"``, ``"9.4x4.3"``, ``"5x4.5x3"``. Anything else (a catalogue name, a path)
        gives None.

    Returns
    -------
    tuple of (float, float, int or None) or None
        ``(diameter_in, pitch_in, n_blades)``, ``n_blades`` None where the designation has no
        third figure. The figures are not range-checked here (:func:`propeller_from_size`
        does).
    """
    if not isinstance(spec, str):
        return None
    m = _SIZE_RE.fullmatch(spec)
    if m is None:
        return None
    return float(m["D"]), float(m["P"]), (int(m["B"]) if m["B"] is not None else None)


def nominal_propeller(diameter: float, pitch: float, n_blades: int = 2, *, name: str | None = None,
                      chord_over_r=None) -> Propeller:
    """A nominal blade of a given size: the helix of ``pitch`` on the catalogue's median chord.

    Parameters
    ----------
    diameter : float
        Tip diameter D [m], in [0.5, 100] in (0.0127-2.54 m).
    pitch : float
        Nominal pitch P [m], > 0 and at most 3 D (a blade angle of at most 51.85 deg at 0.75 R).
    n_blades : int, optional
        Blade count, in [1, 20] (default 2).
    name : str, optional
        The Propeller's name; default ``"<D>x<P>"`` in inches (``"9x4.5"``).
    chord_over_r : array_like, shape (18,), optional
        c/R at :data:`R_OVER_R` instead of :data:`CHORD_OVER_R` (validation: a chord shape
        taken without the propeller's family).

    Returns
    -------
    Propeller
        Stations at :data:`R_OVER_R` times R, chord :data:`CHORD_OVER_R` times R, blade angle
        atan(P / (2 pi r)); ``pitch`` set, ``source`` :data:`NOMINAL_SOURCE`.

    Raises
    ------
    ValueError
        Naming the argument: a value that is not a finite number, a diameter outside [0.5, 100]
        in, a pitch <= 0 or > 3 D, a blade count not an integer in [1, 20], a chord shape of
        another length or with a negative value.

    References
    ----------
    The chord: the median of the UIUC Propeller Data Site vol. 1 and 2 geometry files (Brandt &
    Selig, AIAA 2011-1255; Deters, Ananda & Selig, AIAA 2014-2151) and APC PE0 files (v2022-0915);
    the blade angle: the helix of the pitch, the definition of a propeller's geometric pitch.

    Notes
    -----
    The geometry is not a measured one: blind predictions with it carry the error of the
    blade's real chord and angle (docs/validation.md, A propeller known only by its size);
    fitted to a propeller's own load data, the section parameters absorb much of it.
    """
    D = _number("diameter", diameter)
    P = _number("pitch", pitch)
    if not 0.5 * INCH <= D <= 100.0 * INCH:
        raise ValueError(f"diameter must be in [0.5, 100] in ({0.5 * INCH:g}-{100 * INCH:g} m), got {D!r} m")
    if not 0.0 < P <= 3.0 * D:
        raise ValueError(f"pitch must be > 0 and at most 3 diameters ({3 * D:.4g} m), got {P!r} m")
    if isinstance(n_blades, bool) or not isinstance(n_blades, (int, np.integer)) or not 1 <= n_blades <= 20:
        raise ValueError(f"n_blades must be an integer in [1, 20], got {n_blades!r}")
    shape = np.asarray(CHORD_OVER_R if chord_over_r is None else chord_over_r, dtype=float)
    if shape.shape != (len(R_OVER_R),) or not np.all(np.isfinite(shape)) or np.any(shape < 0):
        raise ValueError(f"chord_over_r must be {len(R_OVER_R)} finite values >= 0 (c/R at R_OVER_R)")
    R = D / 2.0
    r = np.asarray(R_OVER_R) * R
    if name is None:
        name = f"{D / INCH:g}x{P / INCH:g}"
    return Propeller(name=name, radius=R, n_blades=int(n_blades), r=r, chord=shape * R,
                     theta=np.arctan(P / (2.0 * math.pi * r)), pitch=P, source=NOMINAL_SOURCE)


#: what a nominal blade costs, measured (tools/nominal_geometry.py validate, 2026-12-02; docs/validation.md): CT rms
#: in % of static CT, median over the catalogue's propellers (UIUC vol. 1 / vol. 2), the nominal blade's and in
#: brackets the propellers' own geometry's
NOMINAL_COST = ("blind 11.9% / 15.5% (own blades 6.9% / 11.6%), fitted to a static run 7.7% / 8.4% (5.0% / 4.8%), "
                "to a static run and a sweep 4.0% / 5.4% (3.5% / 3.4%)")


def propeller_from_size(spec: str, *, diameter_in: float | None = None, n_blades: int | None = None,
                        catalogue_sizes: dict | None = None) -> Propeller | None:
    """The nominal blade of a size designation (:func:`parse_size`), said in a warning; None for
    anything else.

    Parameters
    ----------
    spec : str
        ``"DxP"`` or ``"DxPxB"`` in inches (``"9x4.5"``, ``"5x4.5x3"``), D in [0.5,
        :data:`DESIGNATION_MAX_IN`] in, 0 < P <= 3 D, B in [1, 20].
    diameter_in : float, optional
        Must agree with the designation's D (within 1e-9 in) where given.
    n_blades : int, optional
        The blade count where the designation has no third figure (default 2); must agree
        with it where it has one.
    catalogue_sizes : dict, optional
        Catalogue name -> (diameter_in, pitch_in, n_blades): the propellers of this size and
        blade count are named in the warning (measured blades the user may have meant).

    Returns
    -------
    Propeller or None
        :func:`nominal_propeller` named ``spec`` (stripped), or None where ``spec`` is not a
        size designation.

    Raises
    ------
    ValueError
        ``diameter_in`` or ``n_blades`` unlike the designation's (the message names
        ``diameter_in = `` / ``n_blades = ``), or a figure out of its range (a D past
        :data:`DESIGNATION_MAX_IN` with its size in inches if it were millimetres).

    Warns
    -----
    UserWarning
        Always, where a blade is built: that it is a nominal one, and what such a blade costs
        on the catalogue (:data:`NOMINAL_COST`).
    """
    size = parse_size(spec)
    if size is None:
        return None
    D_in, P_in, B = size
    if diameter_in is not None and abs(diameter_in - D_in) > 1e-9:
        raise ValueError(f"{spec.strip()}: diameter_in = {diameter_in:g} in, where the size designation says "
                         f"{D_in:g} in: leave the diameter out")
    if B is not None and n_blades is not None and n_blades != B:
        raise ValueError(f"{spec.strip()}: n_blades = {n_blades}, where the size designation's third figure says {B}")
    blades = B if B is not None else (n_blades if n_blades is not None else 2)
    if not 0.5 <= D_in <= DESIGNATION_MAX_IN:
        mm = (f" (a size in millimetres, as UIUC's ef, kpf, pl and vp families name theirs, is {D_in / 25.4:.3g}x"
              f"{P_in / 25.4:.3g} in inches)" if D_in > DESIGNATION_MAX_IN else "")
        raise ValueError(f"{spec.strip()}: a size designation D x P [in]: D must be in [0.5, {DESIGNATION_MAX_IN:g}] "
                         f"in, got {D_in:g}{mm}")
    if B is not None and not 1 <= B <= 20:
        raise ValueError(f"{spec.strip()}: a size designation D x P x B: the blade count B must be in [1, 20], "
                         f"got {B}")
    if not 0.0 < P_in <= 3.0 * D_in:
        raise ValueError(f"{spec.strip()}: a size designation D x P [in]: P must be > 0 and at most 3 D "
                         f"({3.0 * D_in:g} in), got {P_in:g}")
    prop = nominal_propeller(D_in * INCH, P_in * INCH, blades, name=spec.strip())
    import warnings

    same = sorted(n for n, size in (catalogue_sizes or {}).items() if size == (D_in, P_in, blades))
    measured = (f"; the catalogue has measured blades of this size: {', '.join(same)} (name one to use it)"
                if same else "")
    warnings.warn(f"{spec.strip()}: no geometry file: a nominal blade ({D_in:g} in diameter, {blades} blades, the "
                  f"helix of the {P_in:g} in pitch on the catalogue's median chord), whose loads are less certain "
                  f"than a measured blade's (on the catalogue, UIUC vol. 1 / vol. 2: {NOMINAL_COST}){measured}",
                  UserWarning, stacklevel=2)
    return prop


def _number(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name} must be a number [m], got {type(value).__name__}")
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return x
