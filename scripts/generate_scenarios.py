#!/usr/bin/env python3
"""Writes the scenario files of data/scenarios/ that come in families
(thesis Tables 4.1 and 4.2, the GEO weeks, the Serra rendezvous and
collision-avoidance cases, the GEO encounter), so that they stay consistent.
Hand-edit this script, not the generated files; run it from the repository
root:

    python3 scripts/generate_scenarios.py           # rewrite them
    python3 scripts/generate_scenarios.py --check   # only compare (exit 1 if any differs)

Every field is documented in data/scenarios/README.md; the published figures
the scenarios reproduce are in data/reference/*.json.
"""
import argparse
import json
import os
import sys

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "scenarios")
DAY = 86400
N_GEO = 7.2921159e-5  # rad/s, thesis HCW mean motion (Earth rotation rate)

THESIS_SPACECRAFT = {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265}
THESIS_RULES = {"max_simultaneous": 1, "min_burn_s": 300, "min_off_same_s": 1200,
                "min_gap_other_s": 300}


# --check: compare instead of writing (names of the files that differ).
CHECK_ONLY = False
DIFFERENT = []


def write(name, scenario):
    path = os.path.join(OUT, name + ".json")
    text = json.dumps(scenario, indent=2) + "\n"
    if CHECK_ONLY:
        try:
            with open(path) as f:
                same = f.read() == text
        except OSError:
            same = False
        if not same:
            DIFFERENT.append(os.path.relpath(path))
        return
    with open(path, "w") as f:
        f.write(text)
    print("wrote", os.path.relpath(path))


def hcw(name, description, x0_m, v0_m_s, days, enforce_from_s=0, time_limit=600, presolve=True):
    solver = {"time_limit_s": time_limit, "relative_gap": 1e-4, "threads": 2}
    if not presolve:
        solver["presolve"] = False
    return {
        "name": name,
        "description": description,
        "model": {"type": "hcw", "mean_motion_rad_s": N_GEO},
        "spacecraft": dict(THESIS_SPACECRAFT, thrusters={"preset": "ideal6"}),
        "initial_state": {"hcw_position_m": x0_m, "hcw_velocity_m_s": v0_m_s},
        "horizon": {"duration_s": days * DAY, "step_s": 300},
        "window": {"half_width_m": 36800, "enforce_from_s": enforce_from_s},
        "operations": dict(THESIS_RULES),
        "objective": "l1",
        "discretisation": {"scheme": "exact_zoh"},
        "solver": solver,
    }


def thesis_tables():
    published_41 = {1: 0.0164, 2: 0.0819, 3: 0.0984, 4: 0.115, 5: 0.131, 6: 0.131, 7: 0.131,
                    8: 0.131}
    drift_41 = {1: 1.7752, 2: 0.8760, 3: 0.6513, 4: 0.4265, 5: 0.2017, 6: 0.2017, 7: 0.2017,
                8: 0.2017}
    for d in range(1, 9):
        write(f"hcw_table41_{d}d", hcw(
            f"hcw_table41_{d}d",
            f"Gazzino 2018, Table 4.1 (sec. 4.3.3, thesis text L4495-L4509): HCW at GEO, ideal 6 "
            f"thrusters (one per face), X0 = [1 km, 0, 0, 0, 0, 0], horizon {d} day(s), 5-min grid, "
            f"+-36.8 km window on y and z at the grid nodes, thesis rules (5/20/5 min). Published: "
            f"consumption {published_41[d]} m/s (L1), final drift term 2x + vy/n = {drift_41[d]} km "
            f"(data/reference/thesis_tables.json, table_4_1).",
            [1000, 0, 0], [0, 0, 0], d))
    published_42 = {1: 1.803, 2: 1.721, 3: 1.705, 4: 1.705, 5: 1.705, 6: 1.705, 7: 1.688}
    for t1 in range(1, 8):
        write(f"hcw_table42_t1_{t1}d", hcw(
            f"hcw_table42_t1_{t1}d",
            f"Gazzino 2018, Table 4.2 (sec. 4.3.3, thesis text L4519-L4543): HCW at GEO, ideal 6 "
            f"thrusters, X0 = [0, 0, 60 km, 0, 0, 0] (outside the window), horizon 7 days, window "
            f"imposed only on [t1, tf] with t1 - t0 = {t1} day(s). Published: consumption "
            f"{published_42[t1]} m/s (L1) (data/reference/thesis_tables.json, table_4_2). CBC "
            f"presolve is off: with it, CBC 2.10.8 spends minutes in the root LP of these models.",
            [0, 0, 60000], [0, 0, 0], 7, enforce_from_s=t1 * DAY, presolve=False))
    write("hcw_10km_infeasible", hcw(
        "hcw_10km_infeasible",
        "Gazzino 2018, sec. 4.3.3 (Fig. 4.10 discussion): X0 = [10 km, 0, 0, 0, 0, 0], 7 days, "
        "window enforced from t0: the thesis reports the problem infeasible (the drift cannot be "
        "corrected before y leaves the window). Expected exit code 3: CBC alone cannot decide it "
        "(it spends minutes in the root LP, with or without presolve), so the solve stops at its "
        "time limit and the prefix diagnosis proves the first 21 h infeasible on their own.",
        [10000, 0, 0], [0, 0, 0], 7, time_limit=30, presolve=False))
    write("hcw_10km_relaxed_2d", hcw(
        "hcw_10km_relaxed_2d",
        "Gazzino 2018, sec. 4.3.3 (Fig. 4.10): the infeasible X0 = [10 km, 0, 0, 0, 0, 0] case "
        "becomes feasible when the window is relaxed on the first 2 days (t1 - t0 = 2 d, chosen "
        "empirically in the thesis). No consumption is published. CBC presolve is off (with it, "
        "CBC 2.10.8 spends minutes in the root LP).",
        [10000, 0, 0], [0, 0, 0], 7, enforce_from_s=2 * DAY, time_limit=300, presolve=False))
    n = N_GEO
    write("hcw_periodic_no_thrust", hcw(
        "hcw_periodic_no_thrust",
        "Gazzino 2018, eq. (4.87) and Fig. 4.7: X0 = [5, 10, -20, 0, -10 n, 0] (km, km/day) is a "
        "periodic drift-free trajectory inside the window: the optimum is no thrust (0 m/s).",
        [5000, 10000, -20000], [0, -10000 * n, 0], 7, time_limit=300))


def geo(name, description, thrusters, disabled=(), time_limit=90, gap=0.01, encoding=None):
    extra = {"transcription": {"encoding": encoding}} if encoding else {}
    return dict({
        "name": name,
        "description": description,
        "model": {"type": "geo", "station_longitude_deg": 118, "epoch": "2034-01-01T00:00:00Z",
                  "perturbations": ["j2", "tesseral", "sun", "moon", "srp"],
                  "area_to_mass_m2_kg": 0.0227},
        "spacecraft": dict(THESIS_SPACECRAFT, thrusters=thrusters, disabled=list(disabled)),
        "initial_state": {"station_point": True},
        "horizon": {"duration_s": 7 * DAY, "step_s": 300},
        "window": {"half_width_deg": 0.05, "enforce_from_s": 0},
        "operations": dict(THESIS_RULES),
        "terminal": {"type": "station_keeping"},
        "objective": "l1",
        "discretisation": {"scheme": "exact_zoh"},
        "solver": {"time_limit_s": time_limit, "relative_gap": gap, "threads": 2},
    }, **extra)


def geo_weeks():
    common = ("One week of GEO station keeping at 118 deg E from the station point (epoch "
              "2034-01-01T00:00:00Z, full perturbation model), +-0.05 deg window in latitude and "
              "longitude, thesis rules (5/20/5 min), 5-min grid, end-of-week station-keeping set "
              "(thesis ch. 5, corrected) so that the week ends in a state that can stay in the window. ")
    anzel = {"preset": "anzel4", "theta_deg": 63.64, "alpha_deg": 7.03}
    write("geo_week_anzel4", geo(
        "geo_week_anzel4",
        common + "The four thesis (Anzel) thrusters NE, SE, NW, SW. Default scenario of `make "
        "demo`: stops at a 1 % gap or after 90 s of solve (under 2 minutes in total on 2 cores).",
        anzel))
    write("geo_week_ideal6", geo(
        "geo_week_ideal6",
        common + "One thruster per face (+R, +T, +N, -R, -T, -N), thesis sec. 5.3.8. Uses the "
        "thesis encoding of the rules (same feasible schedules): with the tight encoding CBC "
        "2.10.8 spends minutes in the root LP of this model. Allow ~3-5 minutes.",
        {"preset": "ideal6"}, time_limit=300, encoding="thesis"))
    write("geo_week_anzel4_failed_ne", geo(
        "geo_week_anzel4_failed_ne",
        common + "Anzel thrusters with NE failed (disabled: forced off), thesis sec. 5.3.7.",
        anzel, disabled=["NE"]))
    from_opm = geo(
        "geo_week_from_opm",
        "The GEO week of geo_week_anzel4 (118 deg E, epoch 2034-01-01T00:00:00Z, full perturbation "
        "model, Anzel thrusters, thesis rules, end-of-week station-keeping set) started from a real "
        "orbit instead of the station point: the CCSDS OPM geo_week_from_opm.opm (a fictitious "
        "satellite's orbit determination 2 h before the week, EME2000, UTC), propagated to the week "
        "start with the nonlinear model and converted to the model's relative equinoctial state. Run "
        "with --oem and --opm-maneuvers to get the plan back as CCSDS files (README).",
        anzel)
    from_opm["initial_state"] = {"opm": {"file": "geo_week_from_opm.opm"}}
    write("geo_week_from_opm", from_opm)


# The GEO encounter: two days (t = 216000 to 388800 s) of the geo_week_anzel4
# week, from the state its plan reached at t = 216000 s (thrustsched solve
# data/scenarios/geo_week_anzel4.json, trajectory.csv row t_s = 216000: the
# linear model's relative equinoctial state). A secondary passes 7 m from the
# optimal plan of those two days without conjunction (geo_2day_anzel4) at
# t_c = 302400 s: position and velocity of that plan at t_c in the local
# frame (x radial, y along-track, z normal; trajectory.csv of
# `thrustsched solve data/scenarios/geo_2day_anzel4.json`, mapped by
# HcwCoordinates) plus the offsets below.
GEO_2DAY_START = [-468.075868490414, 3.42304066864388e-05, 8.8677186757361e-05,
                  1.70290116533708e-05, 8.58407927206972e-05, 0.000315481510424821]
GEO_2DAY_PLAN_AT_TC = ([-2537.3885683, 19032.7025944, -7284.48439884],
                       [-0.0597000034064, 0.28544697203, 0.778966364793])
GEO_TC = 302400
# The same encounter time in the whole week: the position and velocity at t_c
# of the optimal plan of geo_week_anzel4 (trajectory.csv of `thrustsched solve
# data/scenarios/geo_week_anzel4.json`, mapped by HcwCoordinates).
GEO_WEEK_PLAN_AT_TC = ([-758.795258549, 13169.8082635, -6054.64559826],
                       [-0.0211883050959, -0.0709693881115, 0.62460783836])
# Offsets of the secondary from the plan at t_c, and its uncertainty.
GEO_MISS_M, GEO_REL_VELOCITY_M_S = [3.0, -4.0, 5.0], [0.02, 0.2, -0.03]
GEO_SECONDARY_COVARIANCE = [[1e4, 0, 0, 0, 0, 0], [0, 1e6, 0, 0, 0, 0], [0, 0, 1e4, 0, 0, 0],
                            [0, 0, 0, 4e-6, 0, 0], [0, 0, 0, 0, 2.5e-5, 0],
                            [0, 0, 0, 0, 0, 4e-6]]


def geo_encounter(plan_at_tc, cost_budget):
    pos, vel = plan_at_tc
    return {
        "secondary": {"time_s": GEO_TC,
                      "position_m": [round(p + d, 3) for p, d in zip(pos, GEO_MISS_M)],
                      "velocity_m_s": [round(v + d, 6) for v, d in zip(vel, GEO_REL_VELOCITY_M_S)]},
        "covariance": GEO_SECONDARY_COVARIANCE,
        "radius_m": 15,
        "risk_threshold": 1e-4,
        "checks": {"count": 143, "start_s": GEO_TC - 21600, "end_s": GEO_TC + 21600},
        "cost_budget": cost_budget,
        "verification": {"monte_carlo_samples": 100000, "seed": 1},
    }


def geo_2day(name, description, conjunction=None, gap=1e-4):
    s = geo(name, description, {"preset": "anzel4", "theta_deg": 63.64, "alpha_deg": 7.03},
            time_limit=600, gap=gap)
    s["initial_state"] = {"relative_equinoctial": GEO_2DAY_START}
    s["horizon"] = {"start_s": 216000, "duration_s": 2 * DAY, "step_s": 300}
    s["window"] = {"half_width_deg": 0.05, "enforce_from_s": 216000}
    if conjunction:
        s["conjunction"] = conjunction
    return s


def geo_conjunction_cases():
    common = ("Two days (t = 216000 to 388800 s) of GEO station keeping at 118 deg E, from the "
              "state the geo_week_anzel4 plan reaches at t = 216000 s, Anzel thrusters, thesis "
              "rules, +-0.05 deg window, end-of-horizon station-keeping set. ")
    write("geo_2day_anzel4", geo_2day(
        "geo_2day_anzel4", common + "Without conjunction: the reference of geo_2day_anzel4_conjunction."))
    write("geo_2day_anzel4_conjunction", geo_2day(
        "geo_2day_anzel4_conjunction",
        common + "A secondary passes 7 m from the optimal plan of geo_2day_anzel4 at t = 302400 s "
        "(relative velocity 0.2 m/s along-track), with 100 m radial and normal and 1 km "
        "along-track position uncertainty; eps = 1e-4 over +-6 h around the encounter (143 "
        "checks on the grid nodes). The plan must keep the box, the rules and the risk.",
        conjunction=geo_encounter(GEO_2DAY_PLAN_AT_TC, 2.5), gap=0.01))
    week = geo(
        "geo_week_anzel4_conjunction",
        "The GEO week of geo_week_anzel4 (118 deg E, epoch 2034-01-01T00:00:00Z, full "
        "perturbation model, Anzel thrusters, thesis rules, +-0.05 deg window, end-of-week "
        "station-keeping set) with a secondary that passes 7 m from that week's optimal plan in "
        "the middle of the week (t = 302400 s, relative velocity 0.2 m/s along-track), with 100 m "
        "radial and normal and 1 km along-track position uncertainty; eps = 1e-4 over +-6 h "
        "around the encounter (143 checks on the grid nodes). One MILP keeps the box, the rules "
        "and the risk; its extra cost is measured against geo_week_anzel4.",
        {"preset": "anzel4", "theta_deg": 63.64, "alpha_deg": 7.03}, time_limit=900)
    week["conjunction"] = geo_encounter(GEO_WEEK_PLAN_AT_TC, 3.5)
    write("geo_week_anzel4_conjunction", week)


def serra(name, description, a_m, e, nu0, nuf, z0, vz0, zf, vzf, intervals=1000):
    # Serra's out-of-plane axis is y = -h; ours is z = +h: z = -y_Serra (costs unchanged,
    # impulse signs flipped).
    return {
        "name": name,
        "description": description,
        "model": {"type": "yamanaka_ankersen", "semi_major_axis_m": a_m, "eccentricity": e,
                  "true_anomaly_at_epoch_rad": nu0},
        "spacecraft": {"mass_kg": 1000, "isp_s": 300, "thrust_n": 10,
                       "thrusters": {"preset": "ideal6", "use": ["+N", "-N"]}},
        "initial_state": {"hcw_position_m": [0, 0, z0], "hcw_velocity_m_s": [0, 0, vz0]},
        "horizon": {"end_true_anomaly_rad": nuf, "num_intervals": intervals},
        "input_mode": "impulsive",
        "terminal": {"type": "fixed_state", "hcw_position_m": [0, 0, zf],
                     "hcw_velocity_m_s": [0, 0, vzf]},
        "objective": "l1",
        "discretisation": {"scheme": "exact_zoh"},
        "solver": {"time_limit_s": 60, "relative_gap": 1e-9, "threads": 1},
    }


def serra_cases():
    src = "data/reference/serra_rendezvous.json"
    write("serra_geo_circular", serra(
        "serra_geo_circular",
        "Serra 2015, ch. 5 example 1 (GEO circular, [S L3185-3209]): out-of-plane impulsive "
        "rendezvous, a = 42241 km, e = 0, nu from 0 to 5.0265 rad, Serra's [y, vy] from [5000 m, "
        "-1 m/s] to [20 m, -0.1 m/s] (here z = -y). Published optimum 1.0707 m/s; 1000 time "
        "intervals (grid-converged LP value 1.0707). " + src,
        42241e3, 0.0, 0.0, 5.0265, -5000.0, 1.0, -20.0, 0.1))
    write("serra_leo_circular", serra(
        "serra_leo_circular",
        "Serra 2015, ch. 5 example 2 (LEO circular, [S L3211-3233]): a = 8059 km, e = 0, nu from 0 "
        "to 2.5133 rad, [y, vy] from [-2000 m, -3 m/s] to [-10 m, -0.05 m/s]. Published optimum "
        "3.6143 m/s, two impulses at the ends (so any grid containing both ends attains it). " + src,
        8059e3, 0.0, 0.0, 2.5133, 2000.0, 3.0, 10.0, 0.05))
    write("serra_gto_nuf52", serra(
        "serra_gto_nuf52",
        "Serra 2015, ch. 6 example 2 (GTO, [S L3938-3958]): a = 24616 km, e = 0.73074, nu from "
        "0.1 pi to 5.2 rad, [y, vy] from [10000 m, -3 m/s] to 0. Published optimum 6.2728 m/s "
        "(+3.1060 at nu = 2.3902, -3.1668 at 3.8930). " + src,
        24616e3, 0.73074, 0.1 * 3.141592653589793, 5.2, -10000.0, 3.0, 0.0, 0.0))
    write("serra_gto_nuf3", serra(
        "serra_gto_nuf3",
        "Serra 2015, ch. 6 example 2 (GTO, [S L3960-3980]): as serra_gto_nuf52 with nu_f = 3 rad. "
        "Published optimum 8.7572 m/s (+7.8311 at nu = 1.8924, -0.9261 at 3). " + src,
        24616e3, 0.73074, 0.1 * 3.141592653589793, 3.0, -10000.0, 3.0, 0.0, 0.0))
    di_common = {
        "model": {"type": "double_integrator"},
        "initial_state": {"hcw_position_m": [0, 0, 0], "hcw_velocity_m_s": [0, 0, 0]},
        "terminal": {"type": "fixed_state", "hcw_position_m": [1, 0, 0],
                     "hcw_velocity_m_s": [0, 0, 0]},
        "objective": "l1",
        "discretisation": {"scheme": "exact_zoh"},
    }
    write("serra_double_integrator_impulsive", dict(
        {"name": "serra_double_integrator_impulsive",
         "description": "Serra 2015, sec. 5.2 double integrator ([S L2862-2925]): x'' = u, from "
                        "(0, 0) to (1 m, 0) in 1 s, minimum sum |impulse|. Published optimum 2 "
                        "(+1 at t = 0, -1 at t = 1): exact on any grid containing both ends. " + src,
         "spacecraft": {"mass_kg": 1, "isp_s": 300, "thrust_n": 1,
                        "thrusters": {"custom": [{"name": "+X", "direction_rtn": [1, 0, 0]},
                                                 {"name": "-X", "direction_rtn": [-1, 0, 0]}]}},
         "horizon": {"duration_s": 1, "num_intervals": 10},
         "input_mode": "impulsive",
         "solver": {"time_limit_s": 30, "relative_gap": 1e-9, "threads": 1}},
        **di_common))
    write("serra_double_integrator_onoff", dict(
        {"name": "serra_double_integrator_onoff",
         "description": "Serra 2015, sec. 5.2 double integrator with on-off thrust of fixed "
                        "magnitude U = 8 m/s^2 (8 N on 1 kg), rest to rest over 1 m in 1 s, 100 "
                        "intervals. Continuous-time optimum 2.3431 m/s (two end pulses of 0.14645 s); "
                        "on this grid the optimum is 2.4 m/s exactly (15 intervals each way: 14 "
                        "cannot reach 1 m since k (100 - k) >= 1250 needs k >= 15) [derived]. " + src,
         "spacecraft": {"mass_kg": 1, "isp_s": 300, "thrust_n": 8,
                        "thrusters": {"custom": [{"name": "+X", "direction_rtn": [1, 0, 0]},
                                                 {"name": "-X", "direction_rtn": [-1, 0, 0]}]}},
         "horizon": {"duration_s": 1, "num_intervals": 100},
         "operations": {"max_simultaneous": 1},
         "solver": {"time_limit_s": 60, "relative_gap": 1e-6, "threads": 1}},
        **di_common))


def serra_avoidance(case, budget_m_s, time_limit):
    """Serra 2015 ch. 4 risk selection (Problem 10) from data/reference/serra_avoidance.json."""
    rs = case["risk_selection"]
    src = "data/reference/serra_avoidance.json"
    covariance = [list(row) for row in case["covariance_serra"]]
    fix = case.get("covariance_correction")
    correction = ""
    if fix:
        i, j = fix["entry"]
        covariance[i][j] = covariance[j][i] = fix["used"]
        correction = (f"The printed cov({fix['entry_names'][0]}, {fix['entry_names'][1]}) = "
                      f"{fix['printed']} has the wrong sign (evidence in the reference file): "
                      f"{fix['used']} is used. ")
    name = "serra_avoidance_" + case["example"]
    ex = case["example"][-1]
    return {
        "name": name,
        "description": (
            f"Serra 2015, ch. 4 example {ex} ({case['title']}, [S {case['lines']}]): impulsive "
            f"collision avoidance by risk selection (Problem 10), {rs['N']} impulse dates on "
            f"[{case['t_lo_s']}, {case['t_hi_s']}] s, {rs['N_checks']} check times, cube of R = "
            f"{case['radius_m']} m, eps = 1e-4 over the encounter (eps' = 1e-4 s / duration), return "
            f"to the nominal orbit. Published: {rs['cost_mm_s']} mm/s ({rs['solver']}, "
            f"{rs['cpu_s']} s), unmanoeuvred maximum risk {case['unmanoeuvred_max_risk']}. " + correction +
            f"The covariance {case['equation_covariance']} is not positive semi-definite as printed: "
            f"its negative eigenvalue is clipped to zero (velocities scaled by 1/n). The cost budget "
            f"{budget_m_s} m/s bounds the big-M. " + src),
        "model": {"type": "yamanaka_ankersen", "mean_motion_rad_s": case["mean_motion_rad_s"],
                  "eccentricity": case["eccentricity"], "true_anomaly_rad": case["nu0_rad"],
                  "true_anomaly_time_s": case["t_lo_s"]},
        "spacecraft": {"mass_kg": 1000, "isp_s": 300, "thrust_n": 10,
                       "thrusters": {"preset": "ideal6"}},
        "initial_state": {"hcw_position_m": [0, 0, 0], "hcw_velocity_m_s": [0, 0, 0]},
        "horizon": {"start_s": case["t_lo_s"], "duration_s": case["t_hi_s"] - case["t_lo_s"],
                    "num_intervals": rs["N"] - 1},
        "input_mode": "impulsive",
        "terminal": {"type": "fixed_state", "hcw_position_m": [0, 0, 0],
                     "hcw_velocity_m_s": [0, 0, 0]},
        "objective": "l1",
        "discretisation": {"scheme": "exact_zoh"},
        "conjunction": {
            "frame": "serra_lvlh",
            "secondary": {"time_s": case["t_lo_s"], "position_m": case["secondary_position_m_serra"],
                          "velocity_m_s": case["secondary_velocity_m_s_serra"]},
            "covariance": covariance,
            "covariance_repair": "clip_eigenvalues",
            "radius_m": case["radius_m"],
            "risk_threshold": 1e-4,
            "checks": {"count": rs["N_checks"]},
            "polytope": "cube",
            "cost_budget": budget_m_s,
            "verification": {"monte_carlo_samples": 100000, "seed": 1, "nonlinear": True},
        },
        "solver": {"time_limit_s": time_limit, "relative_gap": 1e-4, "threads": 1},
    }


def serra_avoidance_cases():
    path = os.path.join(os.path.dirname(OUT), "reference", "serra_avoidance.json")
    with open(path) as f:
        ref = json.load(f)
    settings = {"ex1": (0.01, 3600), "ex2": (0.005, 3600)}  # cost budget (m/s), time limit (s)
    for case in ref["cases"]:
        budget, limit = settings[case["example"]]
        write("serra_avoidance_" + case["example"], serra_avoidance(case, budget, limit))


def main():
    parser = argparse.ArgumentParser(
        description="Rewrite the generated scenario files of data/scenarios/ (thesis Tables 4.1 "
                    "and 4.2, the GEO weeks, the Serra rendezvous cases) from this script.")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; list the generated files that differ from what this "
                             "script would write (exit 1 if any)")
    args = parser.parse_args()
    global CHECK_ONLY
    CHECK_ONLY = args.check
    thesis_tables()
    geo_weeks()
    serra_cases()
    serra_avoidance_cases()
    geo_conjunction_cases()
    if CHECK_ONLY:
        for path in DIFFERENT:
            print("differs:", path)
        print("generate_scenarios: %s" % ("all generated files are up to date" if not DIFFERENT
                                          else "%d file(s) differ" % len(DIFFERENT)))
        sys.exit(1 if DIFFERENT else 0)


if __name__ == "__main__":
    main()
