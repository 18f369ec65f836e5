"""File formats: geometry and measurement readers, parameter files, the bundled catalogue."""

from .catalogue import CatalogueEntry, catalogue, get_entry, load_propeller, resolve_propeller
from .param_sets import resolve_params
from .params_file import ParamsFileError, read_params, write_params
from .geometry_files import GeometryFileError, read_apc_pe0, read_geometry, read_uiuc_geometry
from .readers import MeasurementFileError, read_uiuc_static, read_uiuc_sweep

__all__ = [
    "CatalogueEntry", "catalogue", "get_entry", "load_propeller", "resolve_propeller",
    "ParamsFileError", "read_params", "resolve_params", "write_params",
    "GeometryFileError", "MeasurementFileError", "read_apc_pe0", "read_geometry", "read_uiuc_geometry",
    "read_uiuc_static", "read_uiuc_sweep",
]
