"""The columns of a load file that propmap does not read, checked: a quantity it needs under a
name it does not know (an airspeed, advance ratio, flow angle, climb rate or blade pitch that,
left unread, would make every point static, axial or at collective 0) is refused, naming the
column and what to write; one that may mean something else, a force under another name, gets a
note; no rotation-speed or load column is refused with what was looked for
(:func:`propmap.identify.stand.map_columns` calls these)."""

from __future__ import annotations

import re

from .headers import (_NAMES, _UNIT_ONLY_NAMES, AXIAL_RATES, LOOKED_FOR, RATIO_TO_AIRSPEED, UNITS, ColumnMap, _loose,
                      _name_stems, _token, split_header)

#: names that are not read but mean an airspeed, an advance ratio, a flow angle or load coefficients (a file
#: with them and without 'airspeed' / 'incidence_deg' / loads is refused, naming them: map_columns)
_AIRSPEED_LIKE = ("velocity", "v_inf", "vinf", "u_inf", "uinf", "freestream", "free stream", "freestream velocity",
                  "free stream velocity", "freestream speed", "tunnel speed", "wind velocity", "flow speed",
                  "flow velocity", "true airspeed")
_ADVANCE_LIKE = ("advance ratio", "advance_ratio")
_ANGLE_LIKE = ("alpha", "aoa", "angle of attack", "angle_of_attack", "disk angle", "disc angle", "flow angle",
               "alpha p", "alpha s", "alpha d", "alpha disk", "alpha shaft", "alpha tpp")
#: a climb or descent rate, which propmap reads as the airspeed with incidence 0 or 180 deg: refused unless both the
#: airspeed and the incidence are read (left unread, an axial sweep was fitted as static, or a descent as a climb: a
#: wind-tunnel data audit, 2026-11-27); not a bare 'w' (a power in watts)
_AXIAL_RATE_LIKE = ("vz", "v z", "vc", "v c", "climb rate", "climb speed", "descent rate", "descent speed",
                    "rate of climb", "rate of descent", "sink rate", "vertical speed", "vertical velocity",
                    "axial velocity", "axial speed", "axial flow speed",
                    # (descent velocity and descent_velocity_m_s were left unread, every point static: a wind-tunnel
                    # data audit, 2026-11-30)
                    "v descent", "v climb", "descent velocity", "climb velocity", "descending velocity",
                    "climbing velocity")
#: a descent velocity's symbols, one only with a speed's unit (Vd (m/s), V_d_mps; a bare vd is a motor controller's
#: d-axis voltage beside vq, id, iq: a review)
_DESCENT_SYMBOLS = ("vd", "v d")
#: a velocity's symbols, an airspeed where a speed's unit follows after an underscore (V_mps, U_ms, V_kmh were left
#: unread, every point static: a wind-tunnel data audit, 2026-11-30); '_ms' is a millisecond after other names
_VELOCITY_SYMBOLS = ("v", "u", "v0", "u0", "vel", "v tunnel", "u tunnel", "v air", "v wind", "v freestream")
#: a blade pitch setting under another name than collective_deg (its points were fitted at collective 0: an input
#: fuzzing audit, 2026-11-27)
_PITCH_LIKE = ("pitch", "pitch angle", "blade pitch", "blade angle", "collective pitch", "pitch setting",
               "blade pitch angle", "blade setting", "blade setting angle", "pitch_angle", "blade_angle", "blade_pitch")
#: names that may mean either (V a voltage or a velocity, J a joule or an advance ratio, mu a viscosity, a stand's
#: tilt): a note; an angle's is refused beside an airspeed (the points move: an unread angle leaves them axial, a
#: wind-tunnel data audit, 2026-11-27), and a J's or mu's where its values are not all 0 and no airspeed is read
#: (loads_csv.read_loads: an axial sweep's J was read as static, the thrust 11-23% off)
_AMBIGUOUS = {"v": "airspeed", "vd": "airspeed", "j": "airspeed", "mu": "airspeed", "tas": "airspeed",
              "angle": "incidence_deg",
              "tilt": "incidence_deg", "tilt angle": "incidence_deg", "disk tilt": "incidence_deg",
              "disc tilt": "incidence_deg", "rotor tilt": "incidence_deg", "shaft tilt": "incidence_deg",
              "inclination": "incidence_deg",
              "yaw": "incidence_deg", "yaw angle": "incidence_deg"}
#: a balance's axis components (Fx, F_z, Mz, force x), which give the loads only resolved in the rotor's axes
_BODY_COMPONENT = re.compile(r"(f|force|m|moment) ?[xyz]")
#: words of a flow angle's name, and the words that may stand beside them in one (beside an airspeed an unread column
#: named with these alone is refused, one with other words too gets a note: _refuse_unread_flow)
_ANGLE_WORDS = frozenset(("angle", "alpha", "aoa", "tilt", "theta", "beta", "inclination", "incidence"))
_FLOW_WORDS = frozenset(("wind", "flow", "inflow", "freestream", "free", "stream", "shaft", "prop", "propeller",
                         "rotor", "disk", "disc", "attack", "of", "the", "tunnel", "sting", "mount", "rig", "a", "d",
                         "p", "s"))


def _flow_angle_words(base: str) -> str | None:
    """"only" where the column name ``base`` (its unit removed) is a flow angle's words alone
    (``alpha_angle``, ``tilt angle``, ``theta``), "among" where it holds one among other words
    (``phase_angle``, ``theta_75``), else None."""
    words = [w for w in re.split(r"[\s_\-.]+", base.lower()) if w]
    if not _ANGLE_WORDS.intersection(words):
        return None
    return "only" if set(words) <= _ANGLE_WORDS | _FLOW_WORDS else "among"


#: words beside a blade pitch's (pitch, collective, blade angle) that keep a name a blade pitch setting's: the
#: station it is taken at (Blade angle 75% (deg), blade_pitch_75_deg, pitch at 0.75R) and the blade's own words
_PITCH_WORDS = frozenset(("pitch", "collective", "blade", "blades", "angle", "setting", "set", "geometric", "prop",
                          "propeller", "rotor", "at", "r", "tip", "of", "radius", "station", "nominal"))
#: words that make a name with 'pitch' in it something else (an attitude, a rate, a moment, a ratio, a length)
_NOT_PITCH = frozenset(("rate", "moment", "pitching", "ratio", "acc", "accel", "acceleration", "gyro", "imu",
                        "attitude", "body", "vehicle", "sting", "mount", "rig", "tunnel", "shaft", "disk", "disc",
                        "stand", "in", "inch", "inches", "mm", "cm", "m", "diameter", "length", "flow", "wind"))


def _pitch_words(base: str) -> str | None:
    """"only" where the column name ``base`` (its unit removed) names a blade pitch setting and
    where on the blade it is taken (``blade angle 75%``, ``blade_pitch_75_deg``, ``pitch at
    0.75r``), "among" where a blade pitch's words stand among others (``pitch trim``), else None
    (no pitch, or a vehicle's or a rig's pitch, a rate, a moment, a pitch in a length's unit)."""
    words = [w for w in re.split(r"[\s_\-]+", base.lower()) if w]
    if words and _token(words[-1]) in UNITS["angle"]:  # (a unit after an underscore: blade_pitch_75_deg)
        words = words[:-1]
    is_pitch = "pitch" in words or "collective" in words or (
        {"blade", "blades"} & set(words) and {"angle", "setting"} & set(words))
    if not is_pitch or _NOT_PITCH.intersection(words):
        return None
    station = [w for w in words if _station(w)]
    if [w for w in words if w not in _PITCH_WORDS and w not in station]:
        return "among"
    # (the blade's own words or a station make it a blade's; 'angle_pitch', 'prop pitch' may be an attitude's, and a
    # 'geometric pitch' a propeller's nominal pitch, in inches: a review)
    blade = station or {"blade", "blades", "collective", "setting", "set"} & set(words)
    return "only" if blade or " ".join(words) in _loose(_PITCH_LIKE) else None


def _station(word: str) -> bool:
    """Whether a word of a column name is a station along the blade: a fraction or percentage of
    the radius (``75%``, ``0.75``, ``0.75r``, ``75r``, ``3/4``, ``75``), not a channel's number
    (``pitch_1``: a review)."""
    return bool(re.fullmatch(r"\d+(\.\d+)?%|\d*\.\d+r?|\d+r|\d+/\d+", word)) or (
        word.isdigit() and 50 <= int(word) <= 100)


def _blade_pitch(base: str) -> bool:
    """Whether the column name ``base`` (its unit removed) is a blade pitch setting's alone and
    more than a bare 'pitch' or 'pitch angle', which beside an airspeed may be the flow's angle (a
    tunnel sting's)."""
    words = {w for w in re.split(r"[\s_\-]+", base.lower()) if w and _token(w) not in UNITS["angle"]}
    return _pitch_words(base) == "only" and " ".join(sorted(words)) not in ("pitch", "angle pitch")


_COEFFICIENT_NAMES = ("ct", "cp", "cq", "c_t", "c_p", "c_q", "kt", "kq", "k_t", "k_q")
#: speeds in a load file that are not the airspeed (a blade's, the slipstream's: derived or measured behind the
#: propeller); a unit 'kN' is a force (kilonewton), not knots
_NOT_AIRSPEED = re.compile(r"\b(tip|blade|slipstream|induced|exit|wake|jet|outlet|downwash|propwash|rotor)\b")
#: an acceleration's or a vibration's column, whose unit g is no gram (AccX (g), Vibration (g), a_z [g])
_ACCELERATION_LIKE = re.compile(r"^(acc|a[ _]?[xyz]\b)|accel|vibration|\bvib\b|\bimu\b|g[ -]?force|\bgyro")


def _refuse_no_speed(names, cm: ColumnMap, found: str, error) -> None:
    """map_columns without a rotation-speed column: refused, saying where it looks like a
    two-rotor export (columns for rotors A and B), where a column is in a rotation unit under a
    name not read (``Velocita (rpm)``), where a bare ``n`` stands, or like lines above the header."""
    pair = [n for n in names if re.search(r"\b(speed|thrust|torque)\b.*\s[AB](\s*\(.*\))?\s*$", n, re.I)]
    # a bare name read as the rotation speed only with a rotation unit ('n': a count is written so too)
    bare_n = [n for n in names if (b := split_header(n))[1] is None and _UNIT_ONLY_NAMES.get(b[0], ("",))[0] == "rpm"]
    # a column in a rotation unit under a name propmap does not read ('Velocidad (rpm)' was told of lines above the
    # header: a thrust-stand export audit, 2026-11-30)
    def unit(n):  # (a stand log's 'RPM1 - RPM' too)
        return split_header(n)[1] or (n.rsplit(" - ", 1)[1].strip() if " - " in n else None)

    in_rpm = [n for n in names if n.strip() and unit(n) is not None and _token(unit(n)) in UNITS["rotation"]]
    hint = ""
    if pair:
        hint = ("; this looks like a two-rotor export (a coaxial or dual stand, columns for rotors A and B): propmap "
                "fits one isolated rotor, so write one rotor's columns to a file of their own without the A/B "
                "suffix (in a coaxial pair each rotor also works in the other's flow, which propmap leaves out)")
    elif in_rpm:
        hint = (f"; column {in_rpm[0]!r} is in a rotation speed's unit but its name is not read: name it 'rpm' (or "
                f"'Motor speed ({unit(in_rpm[0])})')")
    elif bare_n:
        x = bare_n[0].strip()
        hint = (f"; column {bare_n[0]!r} is read as the rotation speed only with a rotation unit: '{x} (rev/s)', "
                f"'{x} (1/min)' or '{x}_rpm'")
    elif not cm.columns:  # no name read at all: 'RCbenchmark Steps Test' above the header
        hint = ("; lines above the header (a title, the test's settings)? remove them, so that the column names "
                "are the file's first line (a load file's header is looked for in its first 41 lines)")
    raise error(f"no rotation-speed column: looked for {LOOKED_FOR['rpm']}; found {found}{hint}")


def _refuse_no_load(bases: dict, split: dict, found: str, error) -> None:
    """map_columns without a thrust, torque or drag column: refused, naming coefficient columns
    (CT, CP) where they stand instead, and saying how a balance's axis components (Fx, Fz, Mz)
    give the loads where they stand."""
    coeff = [n for n, b in bases.items() if b in _loose(_COEFFICIENT_NAMES)]
    if coeff:
        raise error(f"no load column, but coefficient column(s) {', '.join(map(repr, coeff))}: a CSV gives the "
                    "loads in SI (thrust = CT rho n^2 D^4, torque = CP rho n^2 D^5 / (2 pi), airspeed = J n D); "
                    "UIUC-format files (RPM CT CP static runs, J CT CP eta sweeps) are read as they are")
    # a balance's body-axis components (Fx, Fz, Mz) give the loads once resolved in the rotor's axes: said how (they
    # were told "no load column" only, a wind-tunnel data audit, 2026-12-02)
    body = [n for n, (b, _) in split.items() if _BODY_COMPONENT.fullmatch(b.replace("_", " "))]
    # columns in a force's or a torque's unit under names propmap does not read ('F(KG)', 'T(N.M)' of a stand's log
    # were not named: a thrust-stand export audit, 2026-12-02)
    units = {kind: [n for n, (b, u) in split.items() if u is not None and _token(u) in UNITS[kind]
                    and not _ACCELERATION_LIKE.search(b)] for kind in ("force", "torque")}
    named = [f"{', '.join(map(repr, units[k][:2]))} in a {k}'s unit" for k in ("force", "torque") if units[k]]
    raise error(f"no load column: looked for {LOOKED_FOR['loads']}; found {found}" + (
        f"; {', '.join(map(repr, body[:3]))} look like a balance's axis components: propmap reads the loads in the "
        "rotor's axes, 'thrust' the force along the rotor axis in its direction (-Fz where z points against the "
        "thrust, as a z-down frame's), 'drag' the in-plane force along the in-plane airspeed and 'torque' the moment "
        "about the axis: write those columns, resolved so (docs/conventions.md)" if body else
        f"; column(s) {' and '.join(named)}: name the thrust 'thrust' and the torque 'torque', with their units "
        "(e.g. 'thrust (kgf)')" if named else ""))


def _refuse_wind_axes_and_rates(cm: ColumnMap, split: dict, bases: dict, stems: dict, error) -> None:
    """map_columns' wind-axis lift (refused where the points move, or as a static stand's thrust
    under another name) and a climb or descent rate column (refused unless the airspeed and
    the incidence are read; then a note)."""
    # a tunnel's wind-axis lift and drag are not the rotor's thrust and in-plane force (lift = T sin i + H cos i,
    # drag = H sin i - T cos i at incidence i, the lift positive towards the rotor axis' side)
    lift = [n for n, (b, _) in split.items()
            if re.fullmatch(r"(wind[ _])?lift([ _]force)?([ _](n|mn|kn|kgf|kg|gf|g|lbf|lbs|lb|ozf|oz))?", b)]
    moving = "airspeed" in cm.columns or "incidence_deg" in cm.columns or any(
        stems[n] & _loose(_AIRSPEED_LIKE + _ADVANCE_LIKE + _ANGLE_LIKE) for n in stems)
    if lift and moving:
        raise error(f"column {lift[0]!r}: propmap reads the loads in the rotor's axes (thrust along the axis, 'drag' "
                    "the in-plane force); a wind tunnel's lift L and drag D convert with the incidence i as thrust = "
                    "L sin(i) - D cos(i), in-plane force = L cos(i) + D sin(i) (the lift positive towards the rotor "
                    "axis' side): write those columns instead")
    if lift and "thrust" not in cm.columns:
        raise error(f"column {lift[0]!r}: a static stand's lift is the propeller's thrust: name the column 'thrust' "
                    "(with its unit) to fit it")
    read = {c[0] for c in cm.columns.values()}
    given = [q for q in AXIAL_RATES if q in cm.columns]
    if given:  # a descent or climb rate read as the flow (loads_csv._axial_rate)
        name = cm.columns[given[0]][0]
        if len(given) == 2:
            raise error(f"columns {name!r} and {cm.columns[given[1]][0]!r} both give the axial flow (a descent and a "
                        "climb rate): keep one")
        if "airspeed" in cm.columns and "incidence_deg" in cm.columns:
            cm.columns.pop(given[0])
            cm.notes.append(f"column {name!r} (a {given[0].replace('_', ' ')}) is not read: the airspeed and the "
                            "incidence give the flow")
        elif "airspeed" in cm.columns or "incidence_deg" in cm.columns:
            other = cm.column("airspeed") or cm.column("incidence_deg")
            raise error(f"columns {name!r} (a {given[0].replace('_', ' ')}) and {other!r} both give the flow: keep "
                        "the rate alone (axial flow), or give 'airspeed' with 'incidence_deg' (0 climb, 180 descent)")
    rate = [n for n in bases if n not in read and (
        stems[n] & _loose(_AXIAL_RATE_LIKE)
        or (split[n][0].replace("_", " ") in _DESCENT_SYMBOLS and split[n][1] is not None
            and _token(split[n][1]) in UNITS["speed"])
        or (split[n][1] is None and _speed_stem(split[n][0]) in _DESCENT_SYMBOLS))]
    if rate and "airspeed" in cm.columns and "incidence_deg" in cm.columns:
        cm.notes.append(f"column {rate[0]!r} (a climb or descent rate) is not read: the airspeed and the incidence "
                        "give the flow")
    elif rate:
        raise error(f"column {rate[0]!r} looks like a climb or descent rate, which propmap reads only as 'airspeed' "
                    "(its magnitude, in its unit: 'airspeed (mph)' is read as such) with 'incidence_deg' 0 (climb) "
                    "or 180 (descent): write those columns, or remove it; left unread, its points would be taken as "
                    "static or in the airspeed's direction")


def _refuse_unread_flow(cm: ColumnMap, split: dict, bases: dict, stems: dict, error) -> None:
    """map_columns' airspeed, advance ratio or flow angle under a name propmap does not read
    (refused: every point would be taken as static or axial), or under an ambiguous name (a
    note)."""
    # a wind-tunnel file's airspeed or angle under a name propmap does not read would leave every point static
    flow = any(q in cm.columns for q in ("airspeed", *AXIAL_RATES))  # (a descent or climb rate gives an airspeed)
    for quantity, similar, what, read_as, default in (
            ("airspeed", _AIRSPEED_LIKE + _ADVANCE_LIKE, "an airspeed or advance ratio",
             "'airspeed' [m/s] (an advance ratio as airspeed = J n D)", "static (airspeed 0)"),
            ("incidence_deg", _ANGLE_LIKE, "a flow angle",
             "'incidence_deg', the angle between the airspeed and the rotor axis (0 axial climb, 90 edgewise, 180 "
             "axial descent; a blade pitch setting as 'collective_deg')",
             # (a descent or climb rate sets 0 or 180 deg by its sign: 'incidence 0' misled there, a review, 2026-12-01)
             "in axial flow (incidence 0 or 180 deg by the rate's sign)" if any(q in cm.columns for q in AXIAL_RATES)
             else "in axial flow (incidence 0)")):
        if quantity in cm.columns or (quantity == "airspeed" and flow):
            continue
        similar = _loose(similar)
        like = [n for n in bases if stems[n] & similar]
        # any column propmap does not read whose unit is a speed's (Flight speed (m/s)), or an angle's where the
        # points move (Shaft angle (deg) beside an airspeed): its name may be anything
        kind = "speed" if quantity == "airspeed" else "angle"
        if quantity == "airspeed" or flow:
            like += [n for n, (b, u) in split.items() if b not in _NAMES and u is not None and _token(u) in UNITS[kind]
                     and not (kind == "speed" and ("N" in u or _NOT_AIRSPEED.search(b)))
                     and not (kind == "angle" and _blade_pitch(b))]  # (refused as a blade pitch: 'Blade angle 75%')
        if kind == "speed":  # a velocity's symbol with a speed's unit after an underscore (V_mps, U_ms)
            like += [n for n, (b, u) in split.items() if u is None and b not in _NAMES and n not in like
                     and _speed_stem(b) in _loose(_VELOCITY_SYMBOLS)]
        if kind == "angle" and flow:  # an angle's unit after an underscore (tilt_deg, beta_rad)
            like += [n for n, (b, u) in split.items() if u is None and b not in _NAMES and "_" in b
                     and _token(b.rsplit("_", 1)[1]) in UNITS["angle"] and n not in like
                     and not re.search(r"temp", b)  # (temp_deg, motor_temp_degrees: a temperature)
                     and not _blade_pitch(b)]
            # a name of a flow angle's words alone, without a unit or in an angle's (alpha_angle, tilt_angle, theta,
            # wind_angle, alpha_prop were left unread beside an airspeed, every point axial: 28% thrust error, exit 0,
            # a wind-tunnel data audit, 2026-12-02); one with other words too (phase_angle, coning angle, theta_75,
            # alpha_filter: a review) gets a note below; a blade pitch's name is refused as such after this
            like += [n for n, (b, u) in split.items() if b not in _NAMES and n not in like
                     and (u is None or _token(u) in UNITS["angle"]) and _flow_angle_words(b) == "only"
                     and not (_name_stems(n) | {b}) & _loose(_PITCH_LIKE)]
        if like:
            joule = " (an energy in joules: give its unit, 'energy (J)')" if like[0].strip().lower() == "j" else ""
            unit = split[like[0]][1] if like[0] in split else None
            suffix = like[0].strip()[len(_speed_stem(split[like[0]][0]) or ""):].lstrip("_ ") if (
                unit is None and like[0] in split and _speed_stem(split[like[0]][0]) is not None) else ""
            if kind == "speed" and unit is not None and _token(unit) in UNITS[kind]:
                todo = f"name it 'airspeed ({unit})' (its unit is read)"  # ('converted' misled for m/s: an audit)
            elif kind == "speed" and suffix:  # (V_mps: likewise, a review)
                todo = f"name it 'airspeed_{suffix}' (its unit is read)"
            else:
                todo = "rename it, converted"
            raise error(f"column {like[0]!r} looks like {what}, which propmap reads only as {read_as}: {todo}, or "
                        f"remove it; left unread, every point would be taken as {default}{joule}")
        maybe = [n for n, b in bases.items() if _AMBIGUOUS.get(b) == quantity]  # (no underscores in its keys)
        if quantity == "incidence_deg" and flow:  # (an angle's word among others: a note, a review, 2026-12-02)
            other = [n for n, (b, u) in split.items() if b not in _NAMES and _flow_angle_words(b) == "among"
                     and (u is None or _token(u) in UNITS["angle"])
                     and not (_name_stems(n) | {b}) & _loose(_PITCH_LIKE)]
            if other:
                cm.notes.append(f"column {other[0]!r} is not read; if it is {what}, name it {read_as} (every point is "
                                f"taken as {default})")
        if maybe and quantity == "incidence_deg" and flow:
            raise error(f"column {maybe[0]!r} looks like {what} beside the airspeed, which propmap reads only as "
                        f"{read_as}: rename it, converted, or remove it; left unread, every point would be taken "
                        f"as {default}")
        if maybe:
            ratio = bases[maybe[0]] in ("j", "mu")  # (an advance ratio is no airspeed: it converts, V = J n D)
            cm.notes.append(f"column {maybe[0]!r} is not read; if it is "
                            + (f"an advance ratio, give the airspeed instead ({RATIO_TO_AIRSPEED})" if ratio else
                               f"{what}, name it {read_as}") + f" (every point is taken as {default})")


def _speed_stem(base: str) -> str | None:
    """The name ``base`` less a speed's unit after an underscore (``v_mps`` -> ``v``, ``u_m_s`` ->
    ``u``), blanks for underscores; None without one."""
    parts = base.split("_")
    for k in (2, 1):
        if len(parts) > k and _token("_".join(parts[-k:])) in UNITS["speed"]:
            return " ".join(parts[:-k])
    return None


def _note_unread_force(cm: ColumnMap, split: dict) -> None:
    """map_columns without a thrust or an in-plane force column: a force column under another name
    ('Force (N)') is named in a note (without a thrust it was left out unsaid and a torque-only fit
    ran: a user-level audit; beside a thrust, an in-plane force 'N (N)', 'H (N)' or 'Fx (N)' was
    left out unsaid and never fitted: a wind-tunnel data audit, 2026-11-30)."""
    # any force unit (a gram thrust under 'Weight (g)', 'Thrust avg (g)' was left unsaid: a thrust-stand export
    # audit, 2026-11-30), but not an accelerometer's or a vibration's g (AccX (g), Vibration (g))
    # (a unit after an underscore too, weight_g, load_kgf; not _n there: sample_n is a count)
    forces = [n for n, (b, u) in split.items() if b not in _NAMES and not _ACCELERATION_LIKE.search(b)
              and (_token(u) if u is not None else b.rsplit("_", 1)[-1] if "_" in b else "") in UNITS["force"]
              and (u is not None or not b.endswith("_n"))]
    # (beside a thrust: where an airspeed is read, the in-plane force's sole place, and not a thrust's or a tare's own
    # column: a static stand's 'Load Cell Left (kgf)', 'Tare weight (g)', 'Thrust std (N)' were told of, a review)
    forces = [n for n in forces if "thrust" not in cm.columns or not re.search(r"thrust|tare", split[n][0])]
    if forces and "thrust" in cm.columns:
        cm.notes.append(f"column(s) {', '.join(map(repr, forces[:3]))} (a force) not read: if one is the in-plane "
                        "force (an H-force, a normal force), name it 'drag' with its unit to fit it (the force across "
                        "the rotor axis, along the in-plane airspeed: docs/conventions.md); only the thrust"
                        + (" and the torque are" if "torque" in cm.columns else " is") + " fitted")
    elif forces:
        cm.notes.append(f"column {forces[0]!r} (a force) is not read: name it 'thrust' (or 'drag', the in-plane "
                        "force) with its unit to fit it; without a thrust column "
                        + ("only the " + " and ".join(q for q in ("drag", "torque") if q in cm.columns)
                           + " is fitted" if {"drag", "torque"} & set(cm.columns) else "nothing is fitted"))


def _note_unread_moment(cm: ColumnMap, split: dict) -> None:
    """map_columns without a torque column: a balance's axis moment in a torque's unit ('Mz
    (ft-lb)', 'M_x (N m)') is named in a note (it was left out unsaid where a force column beside
    it was named: a wind-tunnel data audit, 2026-12-02)."""
    # (a balance's axis moments only: a pitching or yawing moment has its own note, a 'Torque std' or a motor's
    # torque constant is no torque; a review, 2026-12-02)
    moments = [n for n, (b, u) in split.items() if b not in _NAMES and u is not None and _token(u) in UNITS["torque"]
               and _BODY_COMPONENT.fullmatch(b.replace("_", " "))]
    if moments:
        cm.notes.append(f"column(s) {', '.join(map(repr, moments[:3]))} (a moment) not read: if one is the moment "
                        "about the rotor axis, name it 'torque' with its unit to fit it (or 'rolling_moment', the "
                        "moment about the in-plane airspeed's direction: docs/conventions.md)")


def _refuse_pitch_like(names, error, notes: list | None = None) -> None:
    """Refuse a blade pitch setting under another name than collective_deg, in degrees, radians or
    no unit (``Pitch (deg)``, ``pitch``, ``blade_angle_deg``, ``Blade angle 75% (deg)``): left
    unread, every point was taken at collective 0 (an input fuzzing audit, 2026-11-27); a pitch in
    inches is not one. A blade pitch's words among others (``pitch trim``) get a note in
    ``notes`` where one is given."""
    for name in names:
        if not name.strip():
            continue
        b, u = split_header(name)
        if b in _NAMES or not (u is None or _token(u) in UNITS["angle"]):
            continue
        words = _pitch_words(b)
        # (the station's words beside it, 'Blade angle 75% (deg)', 'blade_pitch_75_deg', were left unread, every
        # point at collective 0 without a word, 2026-12-02)
        if (_name_stems(name) | {b}) & _loose(_PITCH_LIKE) or words == "only":
            raise error(f"column {name!r} looks like a blade pitch setting, which propmap reads only as "
                        "'collective_deg' (the angle added to the geometry's blade angles at every station, "
                        "[deg]; a tunnel sting's pitch, the flow's angle to the rotor axis, is 'incidence_deg'): "
                        "rename it, converted (a measured blade angle less the geometry's at the same station), or "
                        "remove it; left unread, every point would be taken at the geometry's blade angles "
                        "(collective 0)")
        if words == "among" and notes is not None:
            notes.append(f"column {name!r} is not read; if it is a blade pitch setting, name it 'collective_deg' (the "
                         "angle added to the geometry's blade angles, [deg]); every point is taken at collective 0")
