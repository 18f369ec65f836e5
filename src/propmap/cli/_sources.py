"""Where a fit's or a comparison's load data come from: the SOURCE arguments read (a catalogue
propeller's UIUC data, UIUC-format files, one CSV), the file's air, a warning where the files
are named for another propeller, and the data's digests recorded in ``[coverage]``. Shared by
``propmap fit loads`` and ``propmap validate``."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import click

from ._common import InputError, PropChoice, _short, theta75_deg, warn
from ._paths import _is_file, refuse_copies

#: the fewest distinct operating points a load fit takes (read_sources' min_points; with fit loads --holdout, of the
#: runs left to fit)
MIN_FIT_POINTS = 6


def catalogue_citation(spec, *, geometry_only: bool = False) -> str:
    """The citation of the catalogue propeller a PROP/--prop argument names ("" for a file or
    none): its geometry's and measurements' sources, or its geometry's alone (``geometry_only``:
    the user's own data on a catalogue geometry)."""
    from ..io.catalogue import catalogue

    entry = catalogue().get(spec) if isinstance(spec, str) else None
    if entry is None:
        return ""
    return entry.citation.split("; measurements:")[0] if geometry_only else entry.citation


def file_digests(sources) -> list[str]:
    """Each SOURCE file's SHA-256 (64 hexadecimal digits; a catalogue name gives none), in order:
    ``[coverage] files_sha256``, which tells ``validate`` which of its files a fit read.

    Parameters
    ----------
    sources : iterable of str or Path

    Returns
    -------
    list of str

    Raises
    ------
    OSError
        A file that cannot be read.
    """
    from ..io.atomic import file_sha256

    return [file_sha256(Path(s)) for s in sources if _is_file(Path(s))]


def data_digest(sources, files=None) -> str:
    """SHA-256 over the SOURCE arguments' contents, whatever their order (each file's digest, the
    digests sorted; a catalogue name: its name): what tells a fit's data from another file of
    the same name (``[coverage] data_sha256``).

    Parameters
    ----------
    sources : sequence of str or Path
        The files (or a catalogue name) a fit read.
    files : list of str, optional
        :func:`file_digests` of ``sources``, where already computed (the files are not read
        again).

    Returns
    -------
    str
        64 hexadecimal digits.

    Raises
    ------
    OSError
        A file that cannot be read.
    """
    import hashlib

    each = iter(file_digests(sources) if files is None else files)  # (in the order of the file sources)
    parts = sorted(bytes.fromhex(next(each)) if _is_file(Path(s)) else str(s).encode() for s in sources)
    return hashlib.sha256(b"".join(parts)).hexdigest()


def read_sources(sources, prop_spec, prop_choice: PropChoice, air, rpm_source=None, pole_pairs=None,
                  min_points: int = MIN_FIT_POINTS):
    """(data, propeller, catalogue entry or None, label) from the SOURCE arguments (a CSV of at
    least ``min_points`` points: 6 to fit, 1 to compare).

    Raises
    ------
    InputError
        A catalogue name beside files or ``--prop``, a SOURCE that is neither a catalogue
        propeller nor a file, a file SOURCE without ``--prop``, copies of one file, stand
        options (``--rpm-source``, ``--pole-pairs``) for data that are no stand export, several
        files that are not all UIUC-format, or the readers' DataError (one line).
    """
    from ..identify import DataError, loads_from_catalogue, loads_from_uiuc_files, read_loads
    from ..io.catalogue import catalogue, get_entry
    from ..io.inputs import short_path
    from ..io.readers import looks_like_uiuc

    def refuse_stand_options(what: str) -> None:  # options of a stand's CSV that would be ignored
        for option, value in (("--rpm-source", rpm_source), ("--pole-pairs", pole_pairs)):
            if value is not None:
                raise InputError(f"{option}: applies to a thrust-stand CSV with optical or electrical speed "
                                 f"columns; SOURCE is {what}, whose rotation speed is the measured rpm")

    if len(sources) == 1 and sources[0] in catalogue():
        if prop_spec is not None:
            raise InputError(f"--prop: SOURCE {sources[0]!r} is a catalogue propeller, fitted with its own "
                             "geometry; --prop must be omitted")
        refuse_stand_options(f"the catalogue propeller {sources[0]!r} (UIUC data)")
        entry = get_entry(sources[0])
        prop = prop_choice.load(sources[0])  # refuses both: the catalogue geometry fixes them
        return loads_from_catalogue(entry, prop.diameter, air=air), prop, entry, sources[0]
    missing = [s for s in sources if not _is_file(s)]
    if missing and missing[0] in catalogue():
        raise InputError(f"SOURCE: {missing[0]!r} is a catalogue propeller: give it alone (its UIUC data), or "
                         f"files only, the propeller as --prop {missing[0]} (a catalogue propeller's data and files "
                         "are not taken together)")
    if missing:
        from ..io.catalogue import near_names

        if len(missing[0]) <= 255 and Path(missing[0]).is_dir():  # (a UIUC download's folder: an audit, 2026-11-30)
            folder = Path(missing[0])
            raise InputError(f"SOURCE: {short_path(folder, quote=True)} is a folder: give the files in it, e.g. "
                             f"{short_path(folder / '*.txt')} (UIUC-format files), or one CSV in it")
        # (a name near a catalogue propeller's, APCE_8x6, got no suggestion where validate's and loads' PROP did)
        hint = near_names(missing[0], catalogue(), otherwise="") if len(missing[0]) <= 255 and len(sources) == 1 else ""
        raise InputError(f"SOURCE: {short_path(missing[0], quote=True)} is neither a catalogue propeller nor a file"
                         + (f" (a name of {len(missing[0])} characters)" if len(missing[0]) > 255 else "")
                         + hint)
    if prop_spec is None:
        raise InputError("--prop: a file SOURCE needs the propeller, as --prop NAME or --prop GEOMETRY_FILE (a "
                         "catalogue name or geometry file; one among the SOURCEs is read as data), or, without a "
                         "geometry file, its size, --prop 9x4.5 (D x P in inches: a nominal blade)")
    refuse_copies(sources, "SOURCE", "its data would count twice")
    other = [s for s in sources if not looks_like_uiuc(s)]
    # (UIUC data files with a UIUC geometry file: what their names give is taken; the file's format asked once)
    from ..io.geometry_files import geometry_format

    if other and len(sources) > 1:  # (said before the geometry's missing blade count: a UIUC file audit, 2026-11-30)
        raise InputError(f"SOURCE: {short_path(other[0])} is not a UIUC-format static (RPM CT CP) or wind-tunnel "
                         "(J CT CP eta) file; several files must all be, or give one CSV at a time")
    named = not other and prop_spec not in catalogue() and geometry_format(prop_spec) == "uiuc"
    prop = geometry_from_uiuc_names(sources, prop_spec, prop_choice, uiuc_geometry=named).load(prop_spec, "--prop")
    set_from_names = False
    if named:
        given, prop = prop, blade_angle_from_uiuc_names(sources, prop_spec, prop)
        set_from_names = prop is not given
    try:
        if not other:
            refuse_stand_options("UIUC-format data")
            warn_other_propeller(sources, prop, angle_set=set_from_names)
            return loads_from_uiuc_files(sources, prop.diameter, air=air), prop, None, "UIUC files"
        data = read_loads(sources[0], min_points=min_points, rpm_source=rpm_source, pole_pairs=pole_pairs)
        return data, prop, None, Path(sources[0]).name
    except DataError as exc:
        raise InputError(f"SOURCE: {exc}") from None


def file_air(data, air, air_choice, what: str = "fit"):
    """The air of a fit (``what``) or a comparison: the file's logged density
    (LoadData.air_density) where no air option is given (the set's viscosity and speed of sound
    kept), said in a note; beside an air option that differs from it by more than 2%, a
    warning. Raises nothing."""
    rho = data.air_density
    if rho is None:
        return air
    given = air_choice.options_given()
    if not given:
        click.echo(f"propmap: note: the {what}'s air density is the file's, {rho:.4g} kg/m^3 (--rho to give another)",
                   err=True)
        return replace(air, rho=rho)
    if abs(air.rho / rho - 1.0) > 0.02:
        warn(f"the air density from {' '.join(given)}, {air.rho:.4g} kg/m^3, is not the file's {rho:.4g} kg/m^3 "
             f"(the {what} takes the option's)")
    return air


#: a UIUC data file's name: the propeller, then "static" and the run id or the run id and the nominal rpm (the run
#: id digits then letters, 2801rd, or letters then digits, rd0989, pg0812, kt0535)
_UIUC_RUN = re.compile(r"(.+?)_(static_[0-9a-z]+|(?:[0-9]{3,4}[a-z]{2}|[a-z]{2}[0-9]{3,4})_[0-9]+)\.txt$",
                       re.IGNORECASE)
#: a hub's blade count at the end of a UIUC propeller name (vol. 2's ``da4022_5x3.75_3b``)
_HUB = re.compile(r"(.+)_([1-9])b", re.IGNORECASE)


def _geometry_base(name: str) -> str:
    """A geometry's propeller name without a file extension of letters or ``.PE0`` (``.txt``, ``.dat``; a name's
    ``4x2.7`` kept), ``_geom`` and a hub's blade count, in lower case. (The geometry reader names a
    UIUC file without ``_geom.txt`` by its whole file name, ``mi_4x2.7.txt``.)"""
    name = re.sub(r"\.([a-z]+|pe0)$", "", name, flags=re.IGNORECASE)
    return re.sub(r"_[1-9]b$", "", re.sub(r"_geom$", "", name, flags=re.IGNORECASE).lower())


#: the APC series UIUC names by a prefix and APC's PE0 files by a suffix (``apce_9x7.5`` is ``9x75E-PERF.PE0``: the
#: catalogue's pairs, tests/test_uiuc_names.py)
_APC_SERIES = {"apce": "e", "apcsf": "sf", "apcsp": ""}


def _apc_designation(named: str) -> str | None:
    """APC's name of the propeller a UIUC name gives (``apce_9x7.5`` -> ``9x75e``, lower case), for
    the series whose names the catalogue pairs with PE0 files; None for another name."""
    m = re.fullmatch(r"(apce|apcsf|apcsp)_(\d+(?:\.\d+)?)x(\d+(?:\.\d+)?)", named)
    return None if m is None else f"{m[2]}x{m[3].replace('.', '')}{_APC_SERIES[m[1]]}"


def _uiuc_run_name(source):
    """(named, bare, hub) of a UIUC data file's name: the propeller it is for (lower case), that
    without a hub's blade count, and the count (None without one); None for another name."""
    m = _UIUC_RUN.match(Path(source).name)
    if m is None:
        return None
    named = m.group(1).lower()
    hub = _HUB.fullmatch(named)
    return named, hub.group(1) if hub else named, int(hub.group(2)) if hub else None


def _mixed_hubs(sources) -> str | None:
    """Where UIUC data files named for one propeller give two blade counts (``da4022_5x3.75_static_...``,
    2 blades by UIUC's names, and ``da4022_5x3.75_3b_...``; a name without a hub suffix is the
    catalogue's count for a catalogue propeller, else 2): the first file of each count, said as
    "A (no suffix: 2 blades) and B (_3b)"; else None."""
    from ..io.catalogue import catalogue

    counts = {}
    for s in sources:
        run = _uiuc_run_name(s)
        if run is not None:
            full, bare, hub = run
            entry = catalogue().get(full)
            n = hub or (entry.n_blades if entry is not None else 2)
            counts.setdefault(bare, {}).setdefault(n, (s, hub))
    for named in counts.values():
        if len(named) > 1:
            return " and ".join(f"{_short(Path(s).name)} ({f'_{h}b' if h else f'no suffix: {n} blades'})"
                                for n, (s, h) in sorted(named.items()))
    return None


def _same_blade(bare: str, base: str) -> bool:
    """Whether data named ``bare`` (a hub's count stripped) are of the blade of the geometry named
    ``base``: the same propeller, a size of its family (``da4052_5x2.65`` of ``da4052``), or the
    same blades set to another angle (``nr640_5_20deg`` of ``nr640_5_15deg``)."""
    from ..io.geometry_files import name_without_blade_angle

    free = name_without_blade_angle(bare)
    return bare == base or bare.startswith(base + "_") or (free != bare and free == name_without_blade_angle(base))


def _is_family_file(base: str) -> bool:
    """Whether a geometry's propeller name gives no size (a family design file, ``da4052_geom``)."""
    from ..io.geometry_files import size_from_name

    return size_from_name(base)[0] is None


def geometry_from_uiuc_names(sources, prop_spec, prop_choice: PropChoice, uiuc_geometry: bool) -> PropChoice:
    """The blade count and diameter a UIUC geometry file lacks, from the UIUC data files named for it.

    A UIUC geometry file (``r/R c/R beta``) states neither; UIUC's data files name their
    propeller (``mi_4x2.7_static_0564rd.txt``), its size (a family geometry file,
    ``da4052_geom.txt``, has none in its name) and, for the 3- and 4-blade hubs of vol. 2 only, the
    blade count (``da4022_5x3.75_3b_...``; a name without it is a 2-blade propeller, UIUC's
    convention, or the catalogue's count for a catalogue propeller, ``pl_triturbo`` 3). Where
    every SOURCE is a UIUC-format file whose name is for the geometry's propeller (or a size of
    its family), a --blades or --diameter-in not given is taken from them, each said in a note
    naming the option that overrides it. Anything else (a CSV, a catalogue PROP, a PE0 file,
    files named for several propellers or another one) leaves ``prop_choice`` as it is, and the
    geometry reader asks for what is missing.

    Parameters
    ----------
    sources : sequence of str
        The SOURCE files.
    prop_spec : str
        --prop: a catalogue name or a geometry file.
    prop_choice : PropChoice
        --diameter-in and --blades as given.
    uiuc_geometry : bool
        Whether every SOURCE is a UIUC-format file (:func:`~propmap.io.readers.looks_like_uiuc`)
        and ``prop_spec`` a UIUC geometry file, not a catalogue name (the caller has asked both).

    Returns
    -------
    PropChoice
        ``prop_choice`` with ``blades`` and ``diameter_in`` filled where the names give them (a
        diameter only within NAME_DIAMETER_RANGE_IN, as the geometry reader takes one from its own
        name; outside it a note says it was not taken; a catalogue propeller named without a size,
        ``pl_triturbo``, the catalogue's); each value taken, and each not taken, is said in a
        one-line note on standard error.

    Raises
    ------
    InputError
        Without --blades, files named for two hubs of one blade (``..._static_...`` and
        ``..._3b_...``): a fit or a comparison is of one count.
    """
    from ..io.catalogue import catalogue
    from ..io.geometry_files import NAME_DIAMETER_RANGE_IN, name_blade_count, size_from_name, size_in_inches_from_name

    if not uiuc_geometry or (prop_choice.blades is not None and prop_choice.diameter_in is not None):
        return prop_choice
    runs = {_uiuc_run_name(s) for s in sources}
    if prop_choice.blades is None and None not in runs and (mixed := _mixed_hubs(sources)):
        raise InputError(f"SOURCE: the UIUC data files' names give two hubs of one blade, {mixed}: a fit or a "
                         "comparison is of one blade count; give the runs of one hub, or --blades to take every file "
                         "as that count")
    if None in runs:
        if prop_choice.blades is None:  # (the geometry reader's 'does not state the blade count' came without a
            # word of why: a UIUC file audit, 2026-11-30)
            odd = next(Path(s).name for s in sources if _uiuc_run_name(s) is None)
            click.echo(f"propmap: note: the blade count is not taken from the UIUC data files' names: {_short(odd)} "
                       "is not named as UIUC's are (NAME_static_RUNID.txt, NAME_RUNID_RPM.txt)", err=True)
        return prop_choice
    if len(runs) != 1:
        return prop_choice
    named, bare, hub = runs.pop()
    base = _geometry_base(Path(prop_spec).name)
    if not _same_blade(bare, base):
        return prop_choice
    blades, diameter_in = prop_choice.blades, prop_choice.diameter_in
    shown = _short(Path(sources[0]).name)
    if blades is None:
        entry = catalogue().get(named)
        # (HQProp's 'hqprop_5.1x3.7x3': 2 blades were said, and warned of as not the name's 3, a geometry audit)
        third = name_blade_count(named) if entry is None and not hub else None
        blades = entry.n_blades if entry is not None else hub if hub else third or 2
        why = ("the catalogue's count for it" if entry is not None else "its hub suffix" if hub else
               "its third size figure" if third else "UIUC's names mark only the 3- and 4-blade hubs, _3b and _4b")
        click.echo(f"propmap: note: {blades} blades, from the UIUC data files' name ({shown}: {why}); give --blades "
                   "if the propeller measured has another count", err=True)
    if diameter_in is None and _is_family_file(base):
        d_in = size_in_inches_from_name(bare)[0]  # (as the geometry reader takes a size from its own name)
        D, _, unit, _ = size_from_name(bare)
        # (its blades on another hub, pl_triturbo_4b: the same blade's diameter, a review)
        own = named if named in catalogue() else bare
        entry = catalogue().get(own)
        if D is None and entry is not None and entry.diameter_in:  # (a catalogue propeller whose name gives no size,
            # pl_triturbo's geometry under its own name: "diameter unknown", a user-level run, 2026-11-29)
            diameter_in = entry.diameter_in
            said = re.sub(r"\s*\(tools/[^)]*\)", "", entry.note or "")  # (the catalogue's note, its tool left out)
            click.echo(f"propmap: note: diameter {diameter_in:.4g} in = {diameter_in * 25.4:.4g} mm, the catalogue's "
                       f"for {own} (the names give none{'; ' + said if said else ''}); give --diameter-in if the "
                       "propeller measured has another", err=True)
        elif d_in is not None:
            diameter_in = d_in
            mm = f" = {D:g} mm" if unit == "mm" else ""
            click.echo(f"propmap: note: diameter {diameter_in:.4g} in{mm}, from the UIUC data files' name ({shown}; "
                       "the geometry file's name gives none); give --diameter-in if the propeller measured has another",
                       err=True)
        elif D is not None:
            lo, hi = NAME_DIAMETER_RANGE_IN
            click.echo(f"propmap: note: the UIUC data files' name ({shown}) gives a diameter of {D:g} {unit}, "
                       f"outside the [{lo:g}, {hi:g}] in taken from a name (a size in millimetres of a family not "
                       "known to give them?): not taken", err=True)
    return replace(prop_choice, blades=blades, diameter_in=diameter_in)


def blade_angle_from_uiuc_names(sources, prop_spec, prop):
    """A geometry's blade set to the angle at 0.75 R that the UIUC data files' names give.

    UIUC vol. 2 names its NR640 runs ``nr640_<D>_<angle>deg`` (Deters, Ananda & Selig, AIAA
    2014-2151): the blades of an adjustable hub set to that angle at 0.75 R. The family file
    ``nr640_geom.txt`` is the design blade at 15 deg; the catalogue's ``nr640_9_20deg`` is that
    blade rotated by +5 deg (its ``beta_offset_deg``), and so is a family file here, where every
    SOURCE is named for one such angle: the blade angle shifted by the same amount at every
    station, said in a note. A geometry named for a setting (``nr640_5_15deg_geom.txt``, the 5 in
    blades measured at 15 deg: 16.6 deg at 0.75 R, its own datum) is rotated by the names'
    difference (+5 deg for ``nr640_5_20deg`` runs, as the catalogue's ``nr640_5_20deg`` is since
    2026-11-29). On UIUC's nr640_5_20deg runs, blind (generic
    set): CT rms 35.2% of static CT with the family file as it is, 6.9% set to 20 deg; 27.9% with
    the measured 15 deg blade as it is, 2.5% rotated. Static run and lowest sweep fitted, four
    sweeps held out: thrust rms 0.036 N with the family file as it is, 0.011 N with either rotated
    (2026-11-29).

    Parameters
    ----------
    sources : sequence of str
        The SOURCE files, every one UIUC-format.
    prop_spec : str
        --prop: a UIUC geometry file (the caller's check; a catalogue PROP and a PE0 file are
        taken as they are, and not passed).
    prop : Propeller
        The propeller --prop gives.

    Returns
    -------
    Propeller
        ``prop`` itself, or with its blade angle theta shifted at every station (a geometry named
        for a size, ``da4052_5x2.65_geom.txt``, and runs of several settings are taken as they are).

    Raises
    ------
    InputError
        A named angle that puts the blade angle beyond +-90 deg at a station (``nr640_5_80deg``
        with the design file, 32 deg at its root: 97 deg), naming the file and the angle.
    """
    import math

    from ..io.geometry_files import blade_angle_from_name

    base = _geometry_base(Path(prop_spec).name)
    runs = [_uiuc_run_name(s) for s in sources]
    if None in runs or len({r[1] for r in runs}) != 1:  # (one blade at one setting; its hubs may differ)
        return prop
    bare = runs[0][1]
    angle, setting = blade_angle_from_name(bare), blade_angle_from_name(base)
    if angle is None or not _same_blade(bare, base) or (setting is None and not _is_family_file(base)):
        return prop
    geom = theta75_deg(prop)
    # (a geometry named for its setting is the blade as measured there, its own datum kept: set by the names'
    # difference; a family file, the design, to the named angle)
    offset = angle - (geom if setting is None else setting)
    if abs(offset) < 0.05:
        return prop
    was = f"{prop.name}'s {geom:.1f} deg" if setting is None else f"{prop.name}, set to {setting:g} deg,"
    click.echo(f"propmap: note: the blade set to {angle:g} deg at 0.75 R, from the UIUC data files' name "
               f"({_short(Path(sources[0]).name)}): {was} rotated by {offset:+.2f} deg at every station (an "
               "adjustable hub's setting, as the catalogue's NR640 blades); give a geometry of the blade as set to "
               "take it as it is", err=True)
    try:
        return replace(prop, theta=prop.theta + math.radians(offset))
    except ValueError as exc:  # (was the bare "theta must be in [-90, 90] deg at every station": no file, no angle)
        raise InputError(f"SOURCE: {_short(Path(sources[0]).name)} is named for the blades set to {angle:g} deg at "
                         f"0.75 R: {prop.name} rotated by {offset:+.2f} deg ({exc}); give a geometry of the blade as "
                         "set") from None


#: a family geometry file's blade angle at 0.75 R farther than this from the helix of the pitch a data file's name
#: gives is warned of [deg] (the catalogue's measured blades lie within -5.2 to +3.6 deg of their names' helices; a
#: DA-series design file, a 0.75 P/D helix, is 5.0-10 deg from the vol. 2 sizes' other pitches: no tolerance
#: separates them all, and 2 of the 136 sized catalogue propellers, mit_4.3x3.5 at -5.2 and mi_4x2.7 at -4.6 deg,
#: would be warned of as family files of their own data, so the warning asks to check)
PITCH_ANGLE_TOLERANCE_DEG = 4.0


def _other_pitch(source, named: str, pitch_ratio: float | None, prop, angle_deg: float | None = None) -> bool:
    """Warn (and return True) when a family geometry file's blade angle at 0.75 R is not the pitch
    the data file's name gives (``da4052_5x2.65_...`` with ``da4052_geom.txt``, the family's design
    at a 0.75 P/D: 17.7 deg where a 2.65 in pitch at 5 in is 12.7 deg), or the blade angle at 0.75 R
    it gives (``angle_deg``: ``nr640_9_20deg`` with ``nr640_geom.txt``, the design at 15 deg). A
    family file is one blade at one pitch; its size is taken from the data's names, its pitch is not."""
    import math

    from ..io.catalogue import catalogue

    geom = theta75_deg(prop)
    target = angle_deg if angle_deg is not None else math.degrees(math.atan(pitch_ratio / (0.75 * math.pi)))
    if abs(geom - target) <= PITCH_ANGLE_TOLERANCE_DEG:
        return False
    ratio = math.pi * 0.75 * math.tan(math.radians(geom))
    hint = (f"; the catalogue's {named!r} is that blade at the named pitch (--prop {named})" if named in catalogue()
            else "")
    what = (f"a blade angle of {angle_deg:g} deg at 0.75 R" if angle_deg is not None else
            f"a P/D of {pitch_ratio:.3g} (a helix's blade angle {target:.1f} deg at 0.75 R)")
    warn(f"SOURCE: {_short(Path(source).name)} is named for {what}, used with the family geometry {prop.name}, "
         f"whose blade angle there is {geom:.1f} deg (a P/D of {ratio:.3g}): a family file is one pitch, its size "
         f"but not its pitch is taken from the names; check that the geometry is the propeller measured{hint}")
    return True


def warn_other_propeller(sources, prop, angle_set: bool = False) -> None:
    """Warn when UIUC files are named for another propeller than --prop's (``apce_10x7_...``
    fitted with ``--prop apce_10x5``): the UIUC name ``<family>_<D>x<P>`` before the run, in any
    case. A hub's blade count in the name (vol. 2's ``da4022_5x3.75_3b_...``, the 2-blade
    geometry file shared), or a catalogue propeller's without one (``da4022_5x3.75_static_...``:
    2 blades), is compared with --blades instead; a family geometry file (``da4002_geom.txt``)
    covers its family's sizes, the size a data file's name gives compared with the geometry's
    diameter (within 5%; read as io.geometry_files.size_from_name reads it), and the pitch it
    gives with the file's blade angle at 0.75 R (within PITCH_ANGLE_TOLERANCE_DEG: a family file
    is one pitch). Files named for the same blades at another setting (``nr640_5_20deg`` with
    ``nr640_5_15deg_geom.txt``) are warned of unless ``angle_set``: the blade was set to their angle
    (:func:`blade_angle_from_uiuc_names`). Files of two hubs of one blade are warned of alone.

    Parameters
    ----------
    sources : sequence of str
        The SOURCE files, every one UIUC-format.
    prop : Propeller
        The propeller they are compared with or fitted to (its name, blade count, diameter and
        blade angle at 0.75 R are checked).
    angle_set : bool, optional
        Whether the blade was set to the angle the files' names give (default False).

    Returns
    -------
    None
        At most one warning, on standard error; raises nothing.
    """
    from ..io.catalogue import catalogue
    from ..io.geometry_files import blade_angle_from_name, name_without_blade_angle, size_in_inches_from_name

    # (a hub's blade count stripped as from the data's names: a _3b catalogue propeller's own files were "named for
    # another propeller")
    base = _geometry_base(prop.name)
    if mixed := _mixed_hubs(sources):  # (a no-suffix static run beside _3b sweeps, with --blades 3, ran without a word)
        warn(f"SOURCE: the UIUC data files' names give two hubs of one blade, {mixed}: every file is taken with "
             f"{prop.n_blades} blades; give the runs of one hub if the others are another blade count")
        return
    for s in sources:
        run = _uiuc_run_name(s)
        if not (run and base):
            continue
        full, named, blades = run
        entry = catalogue().get(full)
        if blades is not None:
            if blades != prop.n_blades:
                warn(f"SOURCE: {_short(Path(s).name)} is named for a {blades}-blade hub ('_{blades}b'), used with "
                     f"{prop.n_blades} blades: give --blades {blades} if that is the hub measured (a fitted section "
                     "would otherwise absorb the blade count)")
                return
        elif entry is not None and entry.n_blades != prop.n_blades:  # (UIUC's 2-blade runs carry no suffix)
            warn(f"SOURCE: {_short(Path(s).name)} is named for the catalogue's {named!r}, a {entry.n_blades}-blade "
                 f"propeller, used with {prop.n_blades} blades: give --blades {entry.n_blades} if that is the hub "
                 "measured (the thrust scales nearly with the blade count)")
            return
        named_free, base_free = name_without_blade_angle(named), name_without_blade_angle(base)
        angles = named != base and base_free != base and named_free != named
        if angles and named_free == base_free:  # (both named for a setting, of one blade)
            if not angle_set:  # (the same blades at another setting: runs of several, or a catalogue PROP)
                settings = {blade_angle_from_name(r[1]) for r in map(_uiuc_run_name, sources) if r is not None}
                advice = ("give the runs of one setting (with a UIUC geometry file the blade is then set to it)"
                          if len(settings) > 1 else f"--prop {full} is the catalogue's blade at that setting"
                          if full in catalogue() else "give the blade's UIUC geometry file to set it to that angle")
                warn(f"SOURCE: {_short(Path(s).name)} is named for the blades set to {blade_angle_from_name(named):g} "
                     f"deg at 0.75 R, used with the geometry {prop.name} as it is; {advice}")
                return
        elif (named != base and not named.startswith(base + "_")
                and _apc_designation(named) != re.sub(r"-perf$", "", base)):  # (APC's own name of a PE0 file, 8x6E)
            warn(f"SOURCE: {_short(Path(s).name)} is named for propeller {full!r}, used with --prop "
                 f"{prop.name!r}; check that they are the same propeller")
            return
        # (a family geometry file covers its sizes: the size the name gives is compared, read as the geometry reader
        # reads a name; one outside its range is no size: "give --diameter-in 130" would be refused)
        d_in, p_in = size_in_inches_from_name(named)
        if d_in:
            if abs(prop.diameter / 0.0254 / d_in - 1.0) > 0.05:
                warn(f"SOURCE: {_short(Path(s).name)} is named for a {d_in:.3g} in propeller, used with a "
                     f"{prop.diameter / 0.0254:.3g} in one ({prop.name}): give --diameter-in {d_in:g} if that is "
                     "the propeller measured")
                return
            angle = blade_angle_from_name(named)
            if ((p_in or angle is not None) and _is_family_file(base)
                    and _other_pitch(s, full, None if p_in is None else p_in / d_in, prop, angle)):
                return
