"""What a rotor map returns: :class:`MapLoads` and :class:`MapWrench` (:class:`propmap.maps.RotorMap`'s
``loads`` and ``wrench``, and their one-point paths), apart from the evaluator that fills them.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["MapLoads", "MapWrench"]


class MapLoads(NamedTuple):
    """Loads interpolated in a map; arrays of the broadcast shape S of the queries, or, for one
    point of real numbers (the scalar path, ``RotorMap.loads(600.0, 5.0, 1.0)``), Python floats
    and bools (``inside`` a bool, not an array: a 0-d array query gets 0-d arrays).

    Attributes
    ----------
    thrust, drag, torque, rolling_moment : ndarray
        T [N], D [N], Q [N m], M_R [N m] as in :class:`propmap.RotorLoads`.
    omega : ndarray
        Omega [rad/s] at which the loads hold: the query's, or under ``out_of_grid="clip"``
        above the grid the highest rpm's (so ``power`` is the boundary point's); below the
        grid the query's, at which the scaled loads hold.
    inside : ndarray of bool
        The query lies in the grid (else it was clipped to it or set to NaN).
    flagged : ndarray of bool
        The query is outside the grid, or a node of its cell or of a neighbour cell (the
        4 x 4 x 4 nodes around it) is flagged vortex_ring or
        multiple_roots or did not converge (the map's measured error does not hold there).
    side_force, pitching_moment : ndarray or float
        Y [N] and M_P [N m] as in :class:`propmap.RotorLoads`, interpolated as the other loads
        where the map holds them (its set has blade flapping, a linear inflow or the dynamic
        stall; ``RotorMap.side_loads``); 0 where it does not (rigid blades, uniform inflow,
        static polar: none by symmetry).
    """

    thrust: np.ndarray
    drag: np.ndarray
    torque: np.ndarray
    rolling_moment: np.ndarray
    omega: np.ndarray
    inside: np.ndarray
    flagged: np.ndarray
    side_force: np.ndarray | float = 0.0
    pitching_moment: np.ndarray | float = 0.0

    @property
    def power(self) -> np.ndarray:
        """P = Q Omega [W]."""
        return self.torque * self.omega


class MapWrench(NamedTuple):
    """Force and moment vectors from a map (as :class:`propmap.RotorWrench`).

    Attributes
    ----------
    force, torque : ndarray, shape S + (3,)
        T z - D e_ip + Y e_adv [N] and -spin (Q z + M_R e_ip) + M_P (e_ip x z) [N m]
        (core.vector.wrench_vectors; Y = M_P = 0 where the map holds none).
    loads : MapLoads
    """

    force: np.ndarray
    torque: np.ndarray
    loads: MapLoads
