"""The one place where rpm and rad/s meet.

propmap works in SI inside (Omega in rad/s); rpm appears only at the CLI and in files, with
the unit in the name (``rpm``, ``rpm_min``). Every conversion goes through :data:`RPM`, so a
value converted in two places agrees to the last bit.
"""

from __future__ import annotations

import math

__all__ = ["RPM", "RPM_MAX"]

#: rad/s per rpm: Omega [rad/s] = rpm * RPM, rpm = Omega / RPM (2 pi / 60 = pi / 30).
RPM = 2 * math.pi / 60
#: the largest whole rpm within the solver's rotation-rate range (Omega <= 1e5 rad/s,
#: :data:`propmap.core.solver.OMEGA_MAX`): 954,929 rpm.
RPM_MAX = float(math.floor(1e5 / RPM))
