"""The command line as the tests call it: one in-process run and its one-line error check."""

from __future__ import annotations

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
