"""The command line as the tests call it: one in-process run and its one-line error check; the
example quadrotor with parameter-set entries, as the vehicle commands' tests build it."""

from __future__ import annotations

import shutil
from pathlib import Path

from propmap.cli.main import main


def run(capsys, *argv):
    """Run ``propmap ARGV...`` in process; return (exit code, stdout, stderr).

    Arguments are passed as strings (paths may be given as ``Path``).
    """
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, err, match=""):
    """Exit 2, one stderr line starting 'propmap: error:' that contains ``match``, no traceback."""
    errors = [line for line in err.strip().splitlines() if line.startswith("propmap: error:")]
    return code == 2 and len(errors) == 1 and match in errors[0] and "Traceback" not in err


def example_quad(tmp_path, top="", rotor_params=None, first_propeller=None):
    """The bundled example quadrotor (four catalogue apce_8x6) written to ``tmp_path / "v.toml"``
    with a top-level entry ``top``, each rotor's ``params`` (None: none) and, where given, another
    propeller on rotor 1, beside a copy of the NeuroBEM flight fit as ``fit.toml`` (a [body] table,
    rho 1.204) for ``top`` or a rotor to name."""
    import propmap as pm

    examples = Path(pm.__file__).parent / "data" / "examples"
    head, *rotors = (examples / "quadrotor.toml").read_text().split("[[rotors]]")
    if first_propeller is not None:
        assert 'propeller = "apce_8x6"' in rotors[0]
        rotors[0] = rotors[0].replace('propeller = "apce_8x6"', f'propeller = "{first_propeller}"')
    extra = [""] * 4 if rotor_params is None else [f'params = "{p}"' if p else "" for p in rotor_params]
    text = head + top + "\n" + "".join("[[rotors]]" + r.rstrip("\n") + "\n" + e + "\n" for r, e in zip(rotors, extra))
    shutil.copy(examples / "neurobem_quadrotor.params.toml", tmp_path / "fit.toml")
    (tmp_path / "v.toml").write_text(text, encoding="utf-8")
    return tmp_path / "v.toml"
