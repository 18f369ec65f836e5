"""`propmap wrench` gives propmap's force error by speed band (stop 91), in `fit flight`'s 3 m/s
bands through the log's fastest sample (its report's open band above 9 m/s would lump a faster
flight's 9-18 m/s together): on a log faster than the training ones, how the error grows with speed.
Data: the NeuroBEM race-track segment (Bauersfeld et al., RSS 2021), the bundled NeuroBEM
quadrotor with the generic set."""

import json
import math

import numpy as np
import pytest

from propmap.cli.main import main

LOG = "bemnn20210218171908seg2.mat"


@pytest.fixture(scope="module")
def run(shared_data, tmp_path_factory):
    out = tmp_path_factory.mktemp("w")

    def go(*extra, log=LOG):
        import contextlib
        import io

        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            code = main(["wrench", str(shared_data / "neurobem_flights" / log), "--vehicle", "neurobem_quadrotor",
                         "--params", "generic", "--out", str(out / "w.csv"), *extra])
        assert code == 0
        return buf.getvalue(), out / "w.csv"
    return go


def test_the_bands_partition_the_samples_and_pool_to_the_logs_F(run):
    text, csv = run("--json")
    d = json.loads(text)
    bands = d["speed_bands"]
    assert [b["band_m_s"] for b in bands] == [[0.0, 3.0], [3.0, 6.0], [6.0, 9.0], [9.0, 12.0]]  # (through 11.5 m/s)
    assert sum(b["n"] for b in bands) == d["samples"] == 12724
    # pooled F over the bands (weighted by samples: F^2 is a mean of squares) is the log's F
    pooled = math.sqrt(sum(b["n"] * b["F"] ** 2 for b in bands) / d["samples"])
    assert pooled == pytest.approx(d["errors"]["propmap (generic)"]["F"], rel=1e-9)
    assert all(b["F"] > 0 for b in bands) and np.isfinite([b["F"] for b in bands]).all()
    # regression values (generic set, calibration of 2026-11-29): the error grows with speed
    assert [round(b["F"], 3) for b in bands] == [1.222, 1.572, 1.666, 1.870]


def test_the_text_gives_them_in_one_line(run):
    text, _ = run()
    line = [ln for ln in text.splitlines() if ln.startswith("propmap's F [N] by speed band: ")]
    assert line == ["propmap's F [N] by speed band: 0-3 m/s 1.222 (2355), 3-6 m/s 1.572 (3471), "
                    "6-9 m/s 1.666 (4950), 9-12 m/s 1.870 (1948)"]


def test_a_slow_log_gets_the_bands_it_reaches(run):
    """The slow figure-8 (3.5 m/s at most): two bands, 0-3 and 3-6 m/s."""
    d = json.loads(run("--json", log="bemnn20210223104803seg2.mat")[0])
    assert [b["band_m_s"] for b in d["speed_bands"]] == [[0.0, 3.0], [3.0, 6.0]]
    assert sum(b["n"] for b in d["speed_bands"]) == d["samples"]
