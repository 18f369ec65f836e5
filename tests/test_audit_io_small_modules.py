"""A mutation audit of core/_numbers, core/air, io/atomic, io/pe0 and io/blade_stations (stop 87,
2026-11-30, a helper session: 58 mutants, 16 surviving the suite, 11 of them changing what a user
sees; each test below fails on its mutant, three re-checked by hand):

- a value quoted in a range error is cut to 60 characters (a 500-character string is not echoed);
- Sutherland's constant S = 110.4 K: the viscosity of the U.S. Standard Atmosphere 1976 to 5e-5
  (the older check's 1e-3 let S = 110 through);
- the SHA-256 of a file larger than one 1 MiB block covers every byte (a map's sidecar records it);
- a PE0 TWIST of exactly 90 deg is read (the range is closed), a repeated STATION is refused
  naming its line, the pitch is the QUOTED column's median, not its mean;
- a blade's stations: stopping at r/R 0.68 refused (0.7 needed), two stations stopping at 0.4
  refused, 0.88 warned of and 0.9 not (0.9 needed), the first-station warning attributed to the
  caller's line.
"""

from __future__ import annotations

import hashlib
import warnings

import numpy as np
import pytest

from propmap import Air
from propmap.core._numbers import checked
from propmap.io.atomic import file_sha256
from propmap.io.blade_stations import GeometryFileError
from propmap.io.pe0 import read_apc_pe0

from .test_audit_readers import _pe0, _quiet


def test_the_value_in_the_message_is_clipped_to_60_characters():
    with pytest.raises(ValueError) as e:
        checked("x", "y" * 500, 0, 1)
    assert str(e.value) == "x must be a finite number in [0, 1], got '" + "y" * 59


def test_sutherlands_law_gives_the_standard_atmospheres_viscosity():
    # U.S. Standard Atmosphere 1976: sea level mu = 1.7894e-5 Pa s; at 11 km (216.65 K) 1.4216e-5 Pa s
    assert Air.isa(0.0).mu == pytest.approx(1.7894e-5, rel=5e-5)
    assert Air.from_conditions(216.65, 22632.06).mu == pytest.approx(1.4216e-5, rel=5e-5)


def test_the_sha256_covers_every_byte_of_a_file_over_one_block(tmp_path):
    """file_sha256 reads in 1 MiB blocks: a 3 MiB file's digest is that of all its bytes."""
    data = bytes(range(256)) * (3 * 4096) + b"tail"
    path = tmp_path / "big.bin"
    path.write_bytes(data)
    assert file_sha256(path) == hashlib.sha256(data).hexdigest()


def test_a_pe0_twist_of_exactly_90_deg_is_accepted(tmp_path):
    """TWIST in [-90, 90] deg, a closed range: 90 itself is read."""
    prop = _quiet(read_apc_pe0, _pe0(tmp_path, twist0=90.0))
    assert np.degrees(prop.theta[0]) == pytest.approx(90.0, rel=1e-12)


def test_a_repeated_pe0_station_is_refused_naming_its_line(tmp_path):
    """Stations must increase: a station equal to the one before (line 7) is refused naming its line,
    not later by Propeller in metres without a line."""
    path = _pe0(tmp_path, stations=[1.0, 1.0, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0])
    with pytest.raises(GeometryFileError, match=r"line 7: STATION = 1 in does not increase \(previous 1 in\)"):
        read_apc_pe0(path)


def test_the_pe0_pitch_is_the_quoted_columns_median_not_its_mean(tmp_path):
    """One outlying QUOTED pitch (the tip's 5.8 in made 9.8 in) leaves the median, 5.4 in, as the pitch."""
    prop = _quiet(read_apc_pe0, _pe0(tmp_path, pitch_tip=9.8))
    assert prop.pitch == pytest.approx(5.4 * 0.0254, rel=1e-12)


def test_a_pe0_blade_ending_at_068_r_is_refused(tmp_path):
    """Stations that stop inside r/R = 0.7 are refused (RADIUS 5 in, the last station 3.4 in)."""
    path = _pe0(tmp_path, stations=[5 * (0.2 + 0.06 * k) for k in range(9)])
    with pytest.raises(GeometryFileError, match=r"the stations stop at r/R = 0\.68: .*at least r/R = 0\.7 is needed"):
        read_apc_pe0(path)


def test_a_two_station_blade_ending_at_04_r_is_refused(tmp_path):
    """Two stations (the fewest a blade takes) that stop at r/R = 0.4 are refused like more would be."""
    with pytest.raises(GeometryFileError, match=r"the stations stop at r/R = 0\.4: the outer blade"):
        read_apc_pe0(_pe0(tmp_path, stations=[1.0, 2.0]))


def test_a_blade_ending_at_088_r_is_warned_of(tmp_path):
    """Stations that stop inside r/R = 0.9 (here 0.88) are read with a warning of the extrapolated tip."""
    with pytest.warns(UserWarning, match=r"the stations stop at r/R = 0\.88: the blade from there to the tip"):
        read_apc_pe0(_pe0(tmp_path, stations=[1.0, 2.0, 3.0, 4.0, 4.4]))


def test_a_blade_ending_at_exactly_09_r_is_not_warned_of(tmp_path):
    """Only stations stopping inside r/R = 0.9 are warned of: a last station at 0.9 R (4.5 of 5 in) is not."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        read_apc_pe0(_pe0(tmp_path, stations=[1.0, 2.0, 3.0, 4.0, 4.5]))
    assert not [w for w in caught if "stations stop" in str(w.message)]


def test_the_first_station_warning_points_at_the_callers_line(tmp_path):
    """The warning of a blade starting outside r/R = 0.4 is attributed to the code that called read_apc_pe0."""
    path = _pe0(tmp_path, stations=[2.5, 3.0, 4.0, 5.0])
    with pytest.warns(UserWarning, match=r"the stations start at r/R = 0\.5") as record:
        read_apc_pe0(path)
    assert [w.filename for w in record if "stations start" in str(w.message)] == [__file__]
