"""A PE0 file's diameter given to fewer decimals beside it (stop 91): `--diameter-in 4.2` beside an
APC PE0 of 4.183 in was refused (an audit of stop 90); the file's diameter rounded to the given's
decimals (none for a whole number), within 2%, is now taken as the same (the file's is used), and
any other is refused as before. The files: the bundled APC 10x7E PE0 (APC Propellers' PE0 geometry) with its RADIUS line
set to 5.04 in."""

from pathlib import Path

import pytest

import propmap as pm
from propmap.io.geometry_files import GeometryFileError, _same_diameter, read_geometry

PE0 = Path(pm.__file__).parent / "data" / "apc_pe0" / "10x7-PERF.PE0"


@pytest.fixture
def ten(tmp_path):
    f = tmp_path / "ten.PE0"
    f.write_text(PE0.read_text().replace(" RADIUS:  5.00 ", " RADIUS:  5.04 "))
    return f


@pytest.mark.parametrize("given", [10.1, 10.08, 10.080001, 10, 10.0])
def test_the_files_diameter_to_fewer_decimals_is_taken(ten, given):
    prop = read_geometry(ten, diameter_in=given)
    assert prop.diameter == pytest.approx(10.08 * 0.0254)  # (the file's, not the given's)


@pytest.mark.parametrize("given", [11, 10.2, 10.05, 9.9, 10.1001])
def test_another_diameter_is_refused(ten, given):
    with pytest.raises(GeometryFileError, match=r"gives its own radius \(diameter 10\.08 in\)"):
        read_geometry(ten, diameter_in=given)


def test_the_rule():
    """Rounded to the given's decimals (none for a whole number) and within 2%: 4.2 and 4.18 for
    4.183 are taken, 10 for 10.08 too (0.8% off); 4 for 4.183 is not (4.4% off), nor 4.17 or 4.3;
    1.2 for 1.183 is (1.4% off); 10.2 for 10.25 is and 10.3 is not (10.25 rounds to 10.2 at one
    decimal: Python's round of its binary value, a little below 10.25)."""
    assert _same_diameter(4.2, 4.183) and _same_diameter(4.18, 4.183) and _same_diameter(1.2, 1.183)
    assert _same_diameter(10, 10.08) and _same_diameter(10.0, 10.08) and not _same_diameter(4, 4.183)
    assert not _same_diameter(4.17, 4.183) and not _same_diameter(4.3, 4.183)
    assert _same_diameter(10.2, 10.25) and not _same_diameter(10.3, 10.25)


def test_a_vehicle_rotors_diameter_beside_a_pe0_file_is_said_in_its_own_key(tmp_path):
    """A vehicle rotor's diameter_m beside a PE0 file other than the file's: the refusal says
    diameter_m in metres (it said diameter_in in inches, the CLI's option: a review)."""
    geo = tmp_path / "p10.PE0"
    geo.write_text(PE0.read_text())
    example = Path(pm.__file__).parent / "data" / "examples" / "quadrotor.toml"
    veh = tmp_path / "v.toml"
    veh.write_text(example.read_text().replace('propeller = "apce_8x6"', 'propeller = "p10.PE0"\ndiameter_m = 0.3'))
    from propmap.vehicle import VehicleFileError

    with pytest.raises(VehicleFileError, match=r"p10\.PE0: diameter_m = 0\.3 m, but a PE0 file gives its own "
                                                  r"radius \(diameter 0\.254 m\): leave diameter_m out"):
        pm.read_vehicle(veh)
    veh.write_text(example.read_text().replace('propeller = "apce_8x6"', 'propeller = "p10.PE0"\ndiameter_m = 0.254'))
    assert pm.read_vehicle(veh).rotors[0].propeller.diameter == pytest.approx(0.254)
