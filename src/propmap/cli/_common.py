"""Helpers shared by the subcommands: one-line input errors (exit code 2), option groups, the propeller and
parameter set a command names and their checks (the air: _air.py; warnings beyond the data: _coverage.py; output
checks: _paths.py).

Heavy modules (numba, SciPy, pandas, matplotlib) are imported inside the functions that
need them, so that ``propmap --help`` and ``propmap props`` start quickly.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
from dataclasses import dataclass
from pathlib import Path

import click

from ..core.units import RPM_MAX

#: the solver's range of the rotation rate, 0 < Omega <= 1e5 rad/s, is RPM_MAX in whole rpm
#: (954,929, so that the bound printed is the bound checked); below RPM_MIN the
#: propeller-convention coefficients (referred to n^2) overflow
RPM_MIN = 1.0
AIRSPEED_MAX = 500.0
#: why a negative incidence is refused, and what a disk angle of attack is (docs/conventions.md)
NEGATIVE_INCIDENCE = (" (the model is symmetric: give the magnitude of a negative incidence; a disk angle of attack "
                      "alpha_d, 0 edgewise and positive with the disk tilted back against the airspeed, is incidence "
                      "90 + alpha_d deg)")


class InputError(click.ClickException):
    """Bad user input: printed as one line, exit code 2."""

    exit_code = 2


_SEPARATORS = tuple(c for c in (os.sep, os.altsep, "/") if c)


class PathArg(click.Path):
    """``click.Path`` giving a ``pathlib.Path`` that refuses an empty or all-blank value: click
    alone turns ``--out ''`` into ``Path('.')``, the working folder (a name of blanks is a
    typing slip, not a file anyone wants)."""

    def __init__(self, *, file: bool = False, text: bool = False, **kwargs) -> None:
        # (text: the value as typed, a str: a vehicle's './quadrotor' is a file, 'quadrotor' a bundled example's name,
        # which Path() would make the same)
        super().__init__(path_type=str if text else Path, **kwargs)
        self.file = file  # an output file: a value ending in a separator names a folder (Path() would drop it)

    def convert(self, value, param, ctx):
        if isinstance(value, str) and not value.strip():
            self.fail("the path is empty" if value == "" else f"the path {value!r} is only blanks", param, ctx)
        if self.file and isinstance(value, str) and value.endswith(_SEPARATORS):
            self.fail(f"{value} names a folder (it ends with {value[-1]!r}): give a file's name", param, ctx)
        return super().convert(value, param, ctx)


def parse_names(option: str, text: str | None, valid=None, what: str = "name") -> tuple[str, ...] | None:
    """The comma-separated names of ``option`` (None when the option was not given).

    Parameters
    ----------
    option : str
        The option, for messages.
    text : str or None
    valid : sequence of str, optional
        The names allowed (the message lists them).
    what : str
        What a name is, for messages ("propeller name").

    Raises
    ------
    InputError
        An empty value or item (``''``, ``','``, ``'a,,b'``: never a silent "all" or
        default), a name given twice, or a name not in ``valid``.
    """
    if text is None:
        return None
    names = [n.strip() for n in text.split(",")]
    if not any(names):
        raise InputError(f"{option}: no {what} in {_short(text)!r}; leave the option out for the default")
    if not all(names):
        raise InputError(f"{option}: an empty {what} in {_short(text)!r} (a stray comma?)")
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError(f"{option}: {_short(', '.join(twice))} given more than once")
    if valid is not None:
        unknown = [n for n in names if n not in valid]
        if unknown:
            raise InputError(f"{option}: unknown {_short(', '.join(unknown))}; valid: {', '.join(valid)}")
    return tuple(names)


def given(ctx: click.Context, *params: str) -> list[str]:
    """The options among ``params`` (parameter names) given on the command line, as typed
    (``--c-name``), whatever their value."""
    from click.core import ParameterSource

    out = []
    for p in ctx.command.params:
        if p.name in params and ctx.get_parameter_source(p.name) not in (ParameterSource.DEFAULT, None):
            out.append(p.opts[0] if p.opts and p.opts[0].startswith("-") else p.name.upper())
    return out


#: this command's warnings in the order they arose, for the --json outputs (:func:`run_warnings`) and for cli.main,
#: which does not print a library warning again that :func:`warn` said (a nominal blade's, said by PROP and by a
#: vehicle file, was said twice): ``caught`` is cli.main's list of the warnings it records (printed at the command's
#: end), ``said`` holds (how many of them had been caught, the text) for each :func:`warn`; ``active`` while cli.main
#: runs a command (emptied after it)
RUN_WARNINGS: dict = {"caught": [], "said": [], "active": False}
_PACKAGE_DIR = str(Path(__file__).parent.parent)


def one_line(text) -> str:
    """``text`` on one line: its runs of white space, line breaks included, as one space."""
    return " ".join(str(text).split())


def warn(message: str) -> None:
    """A one-line warning on stderr (the run goes on; a line break in it, as a path may hold, is
    printed as a space, as the --json outputs list it); recorded in :data:`RUN_WARNINGS`."""
    if RUN_WARNINGS["active"]:
        RUN_WARNINGS["said"].append((len(RUN_WARNINGS["caught"]), str(message)))
    click.echo(f"propmap: warning: {one_line(message)}", err=True)


def package_warning(w) -> bool:
    """Whether a recorded warning (``warnings.WarningMessage``) is one of propmap's own: a
    UserWarning raised in the package's code, which the commands say (other libraries'
    warnings are not said: cli.main)."""
    return issubclass(w.category, UserWarning) and str(w.filename).startswith(_PACKAGE_DIR + os.sep)


def run_warnings() -> list[str]:
    """The warnings this command has said on standard error so far, or will say at its end
    (the library's, which cli.main prints last), in the order they arose, each once and on one
    line, without the ``propmap: warning:`` prefix: the ``warnings`` of every --json output,
    so that a script reading it sees what a user reading the terminal sees.

    Returns
    -------
    list of str
        Empty outside a run of cli.main (the command functions called directly, or after the run).
    """
    if not RUN_WARNINGS["active"]:
        return []
    caught = RUN_WARNINGS["caught"]
    out: list[str] = []
    said = iter(RUN_WARNINGS["said"])
    pending = next(said, None)
    for k in range(len(caught) + 1):
        while pending is not None and pending[0] <= k:
            out.append(pending[1])
            pending = next(said, None)
        if k < len(caught) and package_warning(caught[k]):
            out.append(str(caught[k].message))
    return list(dict.fromkeys(map(one_line, out)))


def with_warnings(record: dict) -> dict:
    """``record`` with ``warnings`` (:func:`run_warnings`) added as its last key where it has
    none."""
    return record if "warnings" in record else {**record, "warnings": run_warnings()}


def radians_like(value_deg: float) -> bool:
    """Whether an incidence given in degrees is pi / 2 or pi to 2-5 digits (1.57, 3.14, 3.1416:
    radians typed into a degrees option); a whole number of degrees is believed."""
    return value_deg != round(value_deg) and any(abs(value_deg - k * math.pi / 2) < 0.005 for k in (1, 2))


def warn_incidence_radians(incidence_deg: float, airspeed: float) -> None:
    """A warning where ``--incidence-deg`` of a point with an airspeed looks like radians
    (:func:`radians_like`): 3.14 was taken as 3.14 deg unsaid (a data audit); ``loads`` and,
    since 2026-12-01, ``trim`` say it."""
    if airspeed > 0 and radians_like(incidence_deg):
        warn(f"--incidence-deg {incidence_deg:g}: in radians? ({incidence_deg:g} rad is "
             f"{math.degrees(incidence_deg):.4g} deg; the option is in degrees)")


def load_prop(spec: str, diameter_in: float | None, blades: int | None, option: str = "PROP"):
    """The Propeller named by PROP (catalogue name, geometry file or size designation), with the file options.

    ``option`` names the argument that gave ``spec`` in the errors: ``PROP``, or ``--prop`` where
    the command's geometry is an option (``fit loads``, ``validate SOURCE...``).

    Raises
    ------
    InputError
        Unknown name, malformed file, or --diameter-in/--blades given for a catalogue
        propeller (whose geometry fixes them) or outside their ranges, or unlike what a PE0 or
        QPROP file states (in the options' names, not the readers' n_blades and diameter_in).
    """
    import warnings

    from ..io.catalogue import catalogue, resolve_propeller

    if spec in catalogue():
        given = [o for o, v in (("--diameter-in", diameter_in), ("--blades", blades)) if v is not None]
        if given:
            raise InputError(f"{' and '.join(given)}: {spec!r} is a catalogue propeller whose geometry fixes "
                             "them; they apply to geometry files")
    if diameter_in is not None and not (math.isfinite(diameter_in) and 0.5 <= diameter_in <= 100):
        raise InputError(f"--diameter-in must be finite and in [0.5, 100] in, got {diameter_in!r}")
    if blades is not None and not 1 <= blades <= 20:
        raise InputError(f"--blades must be an integer in [1, 20], got {blades!r}")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            with _spec_errors(option, spec):
                prop = resolve_propeller(spec, diameter_in=diameter_in, n_blades=blades)
        except InputError as exc:  # (the options named as the user gave them: an audit, stop 100)
            raise InputError(str(exc).replace(": n_blades = ", ": --blades ")
                             .replace(": diameter_in = ", ": --diameter-in ")) from None
    for w in caught:
        if issubclass(w.category, UserWarning):
            warn(str(w.message))
    return prop


@contextlib.contextmanager
def _spec_errors(option: str, spec: str):
    """Raise the KeyError, ValueError or OSError of resolving ``spec`` (a propeller's or a parameter
    set's) in the block as a one-line InputError starting with ``option`` (an OSError's naming the file)."""
    try:
        yield
    except KeyError as exc:
        raise InputError(f"{option}: {exc.args[0]}") from None
    except ValueError as exc:
        raise InputError(f"{option}: {exc}") from None
    except OSError as exc:
        from ..io.inputs import short_path

        raise InputError(f"{option}: {short_path(spec)}: {exc.strerror or exc}") from None


PARAMS_HELP = ("Parameter set: a parameter TOML file, 'generic' (cambered, fitted to the whole catalogue), "
               "'calibrated:NAME' (a catalogue propeller's own fit), 'section:NAME' (a symmetric rotor "
               "section: naca0012|naca0015|naca0018), 'qprop:FILE' (a QPROP propeller file's section aero "
               "lines) or the paper's Table I "
               "(gill2017-soft|gill2017-stiff|gill2017-apc). Default: PROP's calibrated set if it has one, "
               "else 'generic'.")


def load_params(spec: str | None, prop_spec: str | None = None, option: str = "--params"):
    """(params, air, label) for ``spec``; None: the default for the propeller ``prop_spec``.

    The default is the catalogue propeller's calibrated set, else the generic set (for
    geometry files and propellers without measurements).

    Raises
    ------
    InputError
        Unknown set, missing or malformed file; the message starts with ``option``.
    """
    from ..io.param_sets import resolve_params

    if isinstance(spec, str) and not spec.strip():
        raise InputError(f"{option}: the value is empty; leave the option out for the default")
    if spec is None:
        from ..io.calibration import default_params, generic_params
        from ..io.catalogue import catalogue

        # (a geometry file's propeller: the generic set, not a near name's warning)
        p = default_params(prop_spec) if prop_spec in catalogue() else generic_params()
        return p, p.air, p.label
    with _spec_errors(option, spec):
        params = resolve_params(spec)
        air = params.air
    return params, air, spec


def set_collective_deg(params) -> float:
    """A parameter set's own collective (its blade-angle offset) [deg], to 12 digits, so that a
    whole number of degrees written to a file reads back as one (not 3.0000000000000004 or
    29.999999999999996) where a command adds its option's collective and checks the sum."""
    return float(f"{math.degrees(params.collective):.12g}")


def theta75_deg(propeller) -> float:
    """The blade angle theta at 0.75 R [deg] (:meth:`Propeller.theta_75` in degrees).

    Parameters
    ----------
    propeller : Propeller

    Returns
    -------
    float
        theta(0.75 R) [deg], from the disk plane.
    """
    return math.degrees(propeller.theta_75())


#: a fitted blade's angle at 0.75 R (a parameter file's [coverage] theta75_deg) farther than this from the blade run,
#: the command's collective included, is warned of [deg]
BLADE_ANGLE_TOLERANCE_DEG = 1.0
#: what a set fitted to one hub's data did on the same blade's other hubs (docs/validation.md, Blade count)
OTHER_HUB = ("such a set predicted UIUC's 3- and 4-blade hubs from the 2-blade one's data to 1.8-11.0% of static CT, "
             "more blades making less thrust than the model says (docs/validation.md, Blade count)")


def _check_fitted_propeller(propeller, label: str, collective_deg: float = 0.0,
                            collective_range: tuple[float, float] | None = None) -> None:
    """Warn where a parameter file fitted to load data of one propeller (its [coverage]
    ``propeller``, ``diameter_m``, ``n_blades``, written since 2026-11-26) runs another one: of
    another diameter (beyond 1%) or blade count (a user-level audit: such a file ran an 8x6E,
    a 10x7E and a 12 in three-blade propeller without a word); or, at the same size, a blade
    whose angle at 0.75 R with ``collective_deg`` [deg] added is more than
    BLADE_ANGLE_TOLERANCE_DEG from the fitted blade's (``theta75_deg``, since 2026-11-29: a fit of
    UIUC's nr640_5_20deg runs, whose blade was set from their names to 20 deg, ran the family
    file's 15 deg blade again without a word, 13% less thrust). ``collective_range`` (lo, hi)
    [deg]: a points file's collective column instead, which sets the blade as fitted where the
    collective that does lies within it (its rows were checked at 0 deg until 2026-11-29)."""
    from pathlib import Path

    if not label or Path(label).suffix.lower() != ".toml":
        return
    from ..io.params_file import set_coverage

    try:
        cov = set_coverage(label) or {}
    except (OSError, ValueError):  # (its reader says what is wrong where it is read)
        return
    d, b = cov.get("diameter_m"), cov.get("n_blades")
    named = cov.get("propeller")
    from ..io.geometry_files import size_from_name

    # another propeller of one size: a pitch sibling, by the pitch both names give (apce_11x7 on apce_11x8; a
    # user-level audit found it unsaid where a calibrated set of the sibling was warned of). Names without a size,
    # or of the same size written otherwise (the catalogue's apce_8x6 and its PE0 file 8x6E), are not compared
    pitch = [size_from_name(str(n))[1] for n in (named or "", propeller.name)]
    if named and propeller.same_size(d, b) and None not in pitch and abs(pitch[0] / pitch[1] - 1.0) > 0.02:
        warn(f"{propeller.name} runs with {Path(label).name}, fitted to data of {named} (the same diameter and blade "
             "count): if that is another propeller (a pitch sibling), its section parameters carry that propeller's "
             "data and predict this one's no better than the generic set (docs/models.md)")
        return
    if d is None and b is None:
        return
    fitted, blade = cov.get("theta75_deg"), theta75_deg(propeller)
    # a collective sweep's data set the blade at fitted + [low, high] (0 to 0 without one; a collective inside its
    # span was warned of as another blade until 2026-12-01, a user-level audit)
    span = (cov.get("collective_deg_min", 0.0), cov.get("collective_deg_max", 0.0))
    if fitted is not None and collective_range is not None:  # (the row nearest the blades as fitted)
        # (of the column's range, the collective nearest those that set them so, fitted - blade + span)
        collective_deg = min(max(fitted + span[0] - blade, collective_range[0]), collective_range[1])
    now = blade + collective_deg
    nearest = None if fitted is None else min(max(now, fitted + span[0]), fitted + span[1])  # (fitted, no sweep)
    if fitted is not None and propeller.same_size(d, b) and abs(now - nearest) > BLADE_ANGLE_TOLERANCE_DEG:
        given = " with the collective given" if collective_deg else ""
        if collective_range is not None:
            given = (f" with the points' collective_deg column's {collective_deg:g} deg (the column spans "
                     f"{collective_range[0]:g} to {collective_range[1]:g} deg)")
        at = f"{fitted:.1f} deg" if span == (0.0, 0.0) else f"{fitted + span[0]:.1f} to {fitted + span[1]:.1f} deg"
        warn(f"{propeller.name} runs with {Path(label).name}, fitted to the blade set at {at} at 0.75 R; "
             f"this one is at {now:.1f} deg there{given}: if it is the same blade, {nearest - now:+.1f} deg of "
             "collective sets it as fitted (--collective-deg of loads and map)")
        return
    if b is not None and propeller.same_size(d, None) and not propeller.same_size(None, b) and (
            fitted is None or abs(now - nearest) <= BLADE_ANGLE_TOLERANCE_DEG):
        # (the same blade on another hub: 'no better than the generic set' was said of it, which the hubs of UIUC
        # vol. 2 contradict)
        warn(f"{propeller.name} ({propeller.n_blades} blades) runs with {Path(label).name}, fitted to data of "
             f"{cov.get('propeller', 'a propeller')} on {int(round(b))} blades: if it is the same blade on another "
             f"hub, {OTHER_HUB}")
        return
    if not propeller.same_size(d, b):
        shown = ", ".join(x for x in (f"{d:.4g} m" if d is not None else "",
                                      f"{int(round(b))} blades" if b is not None else "") if x)
        warn(f"{propeller.name} ({propeller.diameter:.4g} m, {propeller.n_blades} blades) runs with "
             f"{Path(label).name}, fitted to data of {cov.get('propeller', 'another propeller')} ({shown}): its "
             "section parameters absorb that propeller's geometry and data, so they do not carry to another one "
             "reliably (a set calibrated on a pitch sibling predicts its data no better than the generic set, "
             "docs/models.md)")


def check_section_match(propeller, label: str, collective_deg: float = 0.0,
                        collective_range: tuple[float, float] | None = None) -> None:
    """Warn when a rotor-like blade (core.geometry.rotor_like) runs with the generic set,
    which assumes the cambered sections of hobby propellers (on a symmetric-section rotor
    its hover thrust is far too high); the warning names the section presets. Blade angles
    negative at 0.75 R and on average (a pusher's or mirrored file) are warned of instead. A
    set calibrated on another catalogue propeller (``calibrated:NAME``), or a parameter file fitted to
    another propeller's load data (:func:`_check_fitted_propeller`; ``collective_deg``, the
    command's own added collective [deg], counted in its blade angle, or ``collective_range``, the
    (lo, hi) [deg] of a points file's collective column), is warned of too."""
    import numpy as np

    from ..core.geometry import rotor_like
    from ..io.param_sets import section_presets

    b75 = theta75_deg(propeller)
    if b75 < 0 and np.mean(propeller.theta) < 0:
        warn(f"{propeller.name}: the blade angles are negative ({b75:.1f} deg at 0.75 R): a pusher's or a "
             "mirrored geometry? propmap takes a propeller's blade angles positive, measured from the disk plane "
             "(thrust along the axis; the rotation sense is the rotor's spin, docs/conventions.md): with these the "
             "thrust comes out negative. Give the magnitudes")
        return
    why = rotor_like(propeller)
    if why and label == "generic":
        warn(f"{propeller.name}: {why}. The generic parameters assume a hobby propeller's cambered sections; "
             f"for a symmetric-section rotor give --params section:NAME ({', '.join(section_presets())}) or a "
             "parameter file fitted to its data")
    _check_fitted_propeller(propeller, label, collective_deg, collective_range)
    owner = label[len("calibrated:"):] if label.startswith("calibrated:") else None
    if owner is None or owner == propeller.name:
        return
    match = _catalogue_geometry(owner, propeller)
    if match == "other hub":  # (warned of as no better than the generic set until stop 104: da4022_5x3.75's set
        # predicts its 3-blade hub to 2.5% of static CT, the generic set to 12.7%: docs/cli.md)
        warn(f"{propeller.name} ({propeller.n_blades} blades) runs with {label}, calibrated on the same blade on "
             f"another hub: {OTHER_HUB}")
    elif not match:
        warn(f"{propeller.name} runs with {label}, the set calibrated on another propeller: such a set predicts even a "
             "pitch sibling's data to 6.6% of static CT in the median, no better than the generic set (6.2%; "
             "docs/models.md, The calibrated sets do not pin the response to the collective); give 'generic' or a "
             "set fitted to this propeller's data")


def _catalogue_geometry(name: str, propeller) -> bool | str:
    """Whether ``propeller`` is catalogue propeller ``name``'s blade geometry under another name
    (its APC PE0 file, which the catalogue reads for the APC propellers UIUC gives no geometry
    of, was warned of as "another propeller": a vehicle-designer audit, 2026-11-28): True; its
    blades on a hub of another count (UIUC's ``_3b`` and ``_4b`` of a 2-blade propeller, stop 104):
    ``"other hub"``; else False."""
    from dataclasses import replace

    from ..io.catalogue import load_propeller

    try:
        owner = load_propeller(name)
    except (ValueError, KeyError, OSError):
        return False
    if owner.same_geometry(propeller):
        return True
    return "other hub" if replace(owner, n_blades=propeller.n_blades).same_geometry(propeller) else False


def _short(text, n: int = 80) -> str:
    """``text`` cut to ``n`` characters (a name typed by the user, for a one-line message)."""
    text = str(text)
    return text if len(text) <= n else text[:n - 3] + "..."


def check_point(rpm: float, airspeed: float, incidence_deg: float, where: str = "") -> None:
    """Raise InputError naming the input (the option, ``--rpm``, where no ``where`` is given)
    and its valid range (the solver's ranges)."""
    pre = f"{where}: " if where else "--"  # (the options were named 'rpm', 'incidence_deg': a CLI audit)
    if not (math.isfinite(rpm) and RPM_MIN <= rpm <= RPM_MAX):
        why = (" (a parked propeller, rpm 0, has no coefficients: they are referred to the rotation rate; the "
               "Python API's rotor_loads gives its loads)" if math.isfinite(rpm) and 0 <= rpm < RPM_MIN else "")
        raise InputError(f"{pre}rpm must be finite and in [{RPM_MIN:g}, {RPM_MAX:.0f}], got {rpm!r}{why}")
    if not (math.isfinite(airspeed) and 0 <= airspeed <= AIRSPEED_MAX):
        why = (" (the airspeed is a magnitude: a flow up through the disk, descent, is incidence 180 deg; "
               "docs/conventions.md)" if math.isfinite(airspeed) and -AIRSPEED_MAX <= airspeed < 0 else "")
        raise InputError(f"{pre}airspeed must be finite and in [0, {AIRSPEED_MAX:g}] m/s, got {airspeed!r}{why}")
    if not (math.isfinite(incidence_deg) and 0 <= incidence_deg <= 180):
        why = (NEGATIVE_INCIDENCE if math.isfinite(incidence_deg) and -180 <= incidence_deg < 0 else "")
        raise InputError(f"{pre}{'incidence_deg' if where else 'incidence-deg'} must be finite and in [0, 180] deg, "
                         f"got {incidence_deg!r}{why}")


def fixed(x: float, decimals: int) -> str:
    """``x`` with ``decimals`` decimals, or in scientific notation (4 significant digits) where
    that would show a nonzero value with fewer than two (a 45 mm propeller's power at 3000 rpm
    printed "0.00 W", its trimmed 5e-5 N "0.0001 N", a user-level audit, 2026-11-30); an exact
    0 stays "0.000..."."""
    if x != 0.0 and abs(x) < 10.0 ** (1 - decimals):
        return f"{x:.3e}"
    return f"{x:.{decimals}f}"


class Command(click.Command):
    """A click command that refuses an option given twice (click keeps the last value silently:
    ``--rpm 5000 --rpm 6000`` ran at 6000 rpm, a user-level audit, 2026-11-30); options that
    take several values (``multiple``) and counters excepted, and not where ``--help`` is given
    (the help is printed). Every propmap command is one (tests/test_cli_options.py)."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        if ctx.resilient_parsing:  # (shell completion)
            return super().parse_args(ctx, args)
        _, _, order = self.make_parser(ctx).parse_args(args=list(args))
        if any(isinstance(p, click.Option) and p.is_eager and not p.expose_value for p in order):
            return super().parse_args(ctx, args)  # --help: the help, whatever else is given
        seen = set()
        for param in order:
            if not isinstance(param, click.Option) or param.multiple or param.count or not param.expose_value:
                continue
            if param.name in seen:
                what = ("it is a flag: give it once" if param.is_flag else
                        "it takes one value" if param.nargs == 1 else f"it takes one set of {param.nargs} values")
                names = "/".join(param.opts + param.secondary_opts)  # (--tip-loss and --no-tip-loss are one option)
                raise click.UsageError(f"{names} given more than once ({what})", ctx=ctx)
            seen.add(param.name)
        return super().parse_args(ctx, args)


def geometry_label(propeller) -> str:
    """The geometry's blade angle at 0.75 R and solidity, as ``loads`` and ``trim`` print them (a
    twist or chord misread shows there: the command printed only the diameter and the blade
    count, a geometry audit, 2026-12-02).

    Parameters
    ----------
    propeller : Propeller

    Returns
    -------
    str
        "blade angle at 0.75 R <deg> deg, solidity <sigma>" (:meth:`Propeller.theta_75`,
        :meth:`Propeller.solidity`).
    """
    return (f"blade angle at 0.75 R {math.degrees(propeller.theta_75()):.4g} deg, solidity "
            f"{propeller.solidity():.3g}")


def geometry_record(propeller) -> dict:
    """:func:`geometry_label`'s values for a ``--json`` record.

    Parameters
    ----------
    propeller : Propeller

    Returns
    -------
    dict
        ``theta75_deg`` [deg] and ``solidity`` [-].
    """
    return {"theta75_deg": math.degrees(propeller.theta_75()), "solidity": propeller.solidity()}


def echo_json(obj) -> None:
    """Print ``obj`` as JSON, a record with the command's warnings (:func:`with_warnings`); NaN
    or inf anywhere is a bug, so it raises instead."""
    click.echo(json.dumps(with_warnings(obj) if isinstance(obj, dict) else obj, indent=2, allow_nan=False))


def option_group(name: str, cls, options):
    """A decorator giving a click command ``options`` and handing their values to it as one
    keyword argument ``name``, ``cls(**values)``.

    The options keep their names on the command line and in the click context (so
    :func:`given` still names them); the command function takes one argument per group
    instead of one per option.

    Parameters
    ----------
    name : str
        The command function's keyword argument.
    cls : type
        Called with the options' values by their click parameter names (a dataclass).
    options : list
        ``click.option(...)`` decorators.
    """
    import functools

    def probe():
        pass

    for opt in options:
        opt(probe)
    keys = [p.name for p in probe.__click_params__]

    def decorate(f):
        @functools.wraps(f, updated=())
        def command(*args, **kwargs):
            kwargs[name] = cls(**{k: kwargs.pop(k) for k in keys})
            return f(*args, **kwargs)

        if hasattr(f, "__click_params__"):  # options declared below the group (a copy: f's own list stays f's)
            command.__click_params__ = list(f.__click_params__)
        for opt in reversed(options):
            command = opt(command)
        return command

    return decorate


@dataclass(frozen=True)
class PropChoice:
    """--diameter-in [in] and --blades: what a geometry file may lack."""

    diameter_in: float | None = None
    blades: int | None = None

    def load(self, spec: str, option: str = "PROP"):
        """The Propeller named by ``spec`` (given as ``option``) with these options (:func:`load_prop`)."""
        return load_prop(spec, self.diameter_in, self.blades, option)


prop_options = [
    click.option("--diameter-in", type=float, default=None, help="Diameter [in] for geometry files that lack it (a "
                                                                  "family file beside UIUC data: from their names)."),
    click.option("--blades", type=int, default=None, help="Blade count; required for UIUC geometry files (they do not "
                                                          "state it; beside UIUC data files named for the propeller: "
                                                          "from their names), checked against PE0 files."),
]
#: adds --diameter-in and --blades, passed as ``prop_choice`` (a PropChoice)
with_prop_options = option_group("prop_choice", PropChoice, prop_options)
