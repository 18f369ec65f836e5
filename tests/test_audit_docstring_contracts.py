"""Defects a docstring-contract audit found (2026-11-30, a helper session: each public function's
documented Raises, shapes and types tried against its behaviour): objects of the wrong type met an
AttributeError deep inside instead of the documented TypeError naming the argument, a pathlib.Path
was refused where every reader takes one, and a PE0 file's diameter given as text met a bare
TypeError instead of the GeometryFileError its docstring gives."""

from __future__ import annotations

from pathlib import Path

import pytest

import propmap as pm
from propmap.cases import multinomial_fit
from propmap.identify import (fit_level_flight, level_flight_forces, loads_from_uiuc_files,
                              read_level_flight, rotor_kinematics, sanity_check)
from propmap.io import resolve_propeller
from propmap.io.catalogue import get_entry
from propmap.io.geometry_files import GeometryFileError
from propmap.simexport import check_rotorpy_vehicle, write_export

VEHICLE = "vehicle must be a propmap Vehicle"
DATA = Path(pm.__path__[0]) / "data"


@pytest.fixture(scope="module")
def level_flight():
    veh = pm.read_vehicle("quadrotor")
    return read_level_flight(DATA / "examples" / "level_flight_synthetic.csv", veh), veh


def test_a_wrong_vehicle_is_a_type_error_naming_it(level_flight, apc_params):
    data, _ = level_flight
    for call in (lambda: pm.hover_omega(None, apc_params),
                 lambda: read_level_flight(DATA / "examples" / "level_flight_synthetic.csv", None),
                 lambda: rotor_kinematics(data, None),
                 lambda: level_flight_forces(apc_params, data, None),
                 lambda: check_rotorpy_vehicle(None),
                 lambda: write_export(None, "x.csv", vehicle="quad")):
        with pytest.raises(TypeError, match=VEHICLE):
            call()


def test_the_level_flight_fit_names_wrong_data_and_options(level_flight):
    data, veh = level_flight
    with pytest.raises(TypeError, match=r"data must be LevelFlightData"):
        fit_level_flight(None, veh)
    with pytest.raises(TypeError, match=r"options must be a propmap.identify.FitOptions, got NoneType"):
        fit_level_flight(data, veh, options=None)


def test_wrong_propellers_sets_and_air_are_type_errors(apc8x6, apc_params):
    with pytest.raises(TypeError, match=r"propeller must be a Propeller"):
        multinomial_fit(None, apc_params, 600.0)
    hover = pm.HoverModel.from_model(apc8x6, apc_params, 800.0)
    for call in (hover.CT, hover.CP):
        with pytest.raises(TypeError, match=r"air must be a propmap.Air"):
            call(air=1.2)
    with pytest.raises(TypeError, match=r"air must be a propmap.Air, got float"):
        loads_from_uiuc_files([], 0.2, air=1.2)
    data = pm.identify.loads_from_catalogue(get_entry("apce_8x6"), 0.2032)
    with pytest.raises(TypeError, match=r"params must be AirfoilParams or CamberedParams .*resolve_params"):
        sanity_check(data, apc8x6, params="generic")


def test_a_propeller_may_be_given_as_a_path_and_not_as_a_number():
    geom = DATA / get_entry("apce_8x6").geometry_file
    assert resolve_propeller(geom).radius == resolve_propeller(str(geom)).radius
    with pytest.raises(TypeError, match=r"the propeller must be a catalogue name or a geometry file's path, got int"):
        resolve_propeller(5)


def test_a_pe0_files_diameter_as_text_is_a_geometry_file_error():
    geom = DATA / get_entry("apce_8x6").geometry_file
    with pytest.raises(GeometryFileError, match=r"diameter_in must be a number, got '10'"):
        pm.read_geometry(geom, diameter_in="10")
