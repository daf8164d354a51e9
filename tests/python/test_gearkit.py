#!/usr/bin/env python3
"""The Python module gearkit (python/, docs/python.md), run by ctest as python.gearkit.

Values are checked against independent references (the seeds' worked answers, published
examples, hand formulas written out here) and, separately, against the CLI's JSON for the same
input (consistency: the module must print what `gearkit` prints). Environment: PYTHONPATH holds
build/python, GEARKIT_EXE the gearkit executable, GEARKIT_SOURCE_DIR the source tree.
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import unittest
from fractions import Fraction

import numpy as np

import gearkit

SOURCE = os.environ.get("GEARKIT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("GEARKIT_EXE", os.path.join(SOURCE, "build", "bin", "gearkit"))
DEG = math.pi / 180.0


def example(*parts):
    return os.path.join(SOURCE, "examples", *parts)


def cli(*args):
    """Runs gearkit; returns (status, stdout, stderr)."""
    r = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=120)
    return r.returncode, r.stdout, r.stderr


def cli_json(*args):
    status, out, err = cli(*args, "--format", "json")
    if status != 0:
        raise AssertionError(f"gearkit {' '.join(args)}: status {status}: {err}")
    return json.loads(out)


def cli_error(*args):
    """The CLI's exit-2 line without its 'gearkit: ' prefix."""
    status, _, err = cli(*args)
    assert status == 2, (status, err)
    assert err.startswith("gearkit: ") and err.count("\n") == 1, err
    return err[len("gearkit: "):].rstrip("\n")


def inv(alpha):
    return math.tan(alpha) - alpha


class GearPairTest(unittest.TestCase):
    # OTM 2015 problem 3 (seed 000_bc94d104a9983772.txt): m = 9 mm, z = 10/40, V-0 at a = 225 mm
    # with x = +-(14 - 10)/17. The seed's table (radii, mm): r_b 42.29/169.14, r_c 56.12/186.88,
    # r_f 35.87/166.63, p 28.27, e 12.59/15.68, s 15.68/12.59, alpha' = 20 deg, a' = 225.
    def otm(self):
        return gearkit.gear_pair(z1=10, z2=40, module="9 mm", centre_distance="225 mm", x1=4 / 17)

    def test_otm2015_problem3_table(self):
        g = self.otm()
        for gear, r_b, r_a, r_f, e, s in ((g.gear1, 42.29, 56.12, 35.87, 12.59, 15.68),
                                          (g.gear2, 169.14, 186.88, 166.63, 15.68, 12.59)):
            self.assertAlmostEqual(gear.d_b_mm / 2, r_b, delta=0.005)
            self.assertAlmostEqual(gear.d_a_mm / 2, r_a, delta=0.005)
            self.assertAlmostEqual(gear.d_f_mm / 2, r_f, delta=0.005)
            self.assertAlmostEqual(gear.e_mm, e, delta=0.01)  # the seed cuts e and s to 2 decimals (12.5956 -> 12.59)
            self.assertAlmostEqual(gear.s_mm, s, delta=0.01)
            self.assertAlmostEqual(gear.p_mm, 28.27, delta=0.005)
        self.assertAlmostEqual(g.pair.centre_distance_mm, 225.0, places=9)
        self.assertAlmostEqual(g.pair.alpha_wt_deg, 20.0, places=9)
        self.assertAlmostEqual(g.gear1.x, 4 / 17, places=12)
        self.assertAlmostEqual(g.gear2.x, -4 / 17, places=12)

    def test_si_floats_and_unit_strings_agree_with_the_hand_formulas(self):
        # ISO 21771: d = z m_n / cos beta, d_b = d cos alpha_t, a = (d1 + d2)/2 for x1 = x2 = 0.
        m, z1, z2 = 0.003, 12, 24
        a = gearkit.gear_pair(z1=z1, z2=z2, module=m, pressure_angle=20 * DEG)
        b = gearkit.gear_pair(z1=z1, z2=z2, module="3 mm", pressure_angle="20 deg")
        self.assertEqual(a.to_dict(), b.to_dict())
        self.assertAlmostEqual(a.pair.centre_distance_mm, 3 * (z1 + z2) / 2, places=9)
        self.assertAlmostEqual(a.gear2.d_b_mm, 3 * z2 * math.cos(20 * DEG), places=9)

    def test_v_pair_working_pressure_angle_by_the_involute_function(self):
        # KHK's V pair (examples/gears/README.md): z 12/24, m 3, x 0.6/0.36. ISO 21771:
        # inv alpha_w = inv alpha + 2 tan(alpha) (x1 + x2)/(z1 + z2), a = a_d cos alpha / cos alpha_w.
        g = gearkit.gear_pair(z1=12, z2=24, module="3 mm", x1=0.6, x2=0.36)
        target = inv(20 * DEG) + 2 * math.tan(20 * DEG) * 0.96 / 36
        lo, hi = 0.0, 1.0
        for _ in range(200):  # bisection on the involute function
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if inv(mid) < target else (lo, mid)
        self.assertAlmostEqual(g.pair.alpha_wt_deg, lo / DEG, places=8)
        self.assertAlmostEqual(g.pair.centre_distance_mm, 54 * math.cos(20 * DEG) / math.cos(lo), places=8)
        self.assertAlmostEqual(g.pair.centre_distance_mm, 56.500, delta=0.0005)  # KHK's printed value

    def test_helical_transverse_pressure_angle(self):
        # ISO 21771 example (examples/gears/README.md): tan alpha_t = tan alpha_n / cos beta, 21.2990642859 deg.
        g = gearkit.gear_pair(z1=31, z2=30, module="3.5 mm", helix_angle="21 deg", centre_distance="116.5 mm", x1=0.291,
                              face_width="40 mm")
        self.assertAlmostEqual(g.gear1.alpha_t_deg, math.atan(math.tan(20 * DEG) / math.cos(21 * DEG)) / DEG, places=9)
        self.assertAlmostEqual(g.gear1.alpha_t_deg, 21.2990642859, places=9)
        self.assertAlmostEqual(g.gear1.x + g.gear2.x, 0.651877131252, places=9)

    def test_rating_of_iso_tr_6336_30_example_1(self):
        # ISO/TR 6336-30:2017 example 1, published values (KISSsoft validation table of
        # gfsReboucas/Drivetrain, as tests/gear/test_rating.cpp): F_t = 127352 N, S_H = 1.0285 / 1.0870.
        g = gearkit.read_gear_pair(example("gears", "iso_tr_6336_30_example1.yaml"))
        self.assertAlmostEqual(g.rating.F_t_N, 127352.0, delta=1.0)
        self.assertAlmostEqual(g.rating.gears[0].S_H, 1.0285, delta=0.001)
        self.assertAlmostEqual(g.rating.gears[1].S_H, 1.0870, delta=0.001)
        self.assertIsNone(gearkit.gear_pair(z1=20, z2=40, module=0.002).rating)

    def test_same_json_as_the_cli(self):
        self.assertEqual(self.otm().to_dict(),
                         cli_json("gear", "--z1", "10", "--z2", "40", "--module", "9", "--centre-distance", "225",
                                  "--x1", repr(4 / 17)))
        path = example("gears", "iso_tr_6336_30_example1.yaml")
        self.assertEqual(gearkit.read_gear_pair(path).to_dict(), cli_json("gear", path))
        path = example("gears", "spectrum_stage.yaml")
        self.assertEqual(gearkit.read_gear_pair(path).to_dict(), cli_json("gear", path))

    def test_bad_input_raises_value_error(self):
        with self.assertRaisesRegex(ValueError, r"^argument 'module': expected a length"):
            gearkit.gear_pair(z1=10, z2=40, module="9 deg")
        with self.assertRaisesRegex(ValueError, r"^argument 'z1': "):
            gearkit.gear_pair(z1=0, z2=40, module="9 mm")
        with self.assertRaisesRegex(ValueError, r"^argument 'split': expected balanced"):
            gearkit.gear_pair(z1=10, z2=40, module="9 mm", centre_distance="226 mm", split="even")
        with self.assertRaisesRegex(ValueError, r"^argument 'face_width': expected a length as a number"):
            gearkit.gear_pair(z1=10, z2=40, module="9 mm", face_width=[1])

    def test_bad_file_raises_the_clis_message(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "pair.yaml")
            with open(path, "w") as f:
                f.write("z1: 17\nz2: 103\nmodule: 8 deg\n")
            with self.assertRaises(ValueError) as e:
                gearkit.read_gear_pair(path)
            self.assertEqual(str(e.exception), cli_error("gear", path))
            self.assertIn(f"{path}:3:", str(e.exception))


class TrainTest(unittest.TestCase):
    def test_seed_cvt_ratio_is_the_exact_fraction(self):
        # Seed 004 exercise 2: tau_1 = w23/w1 = -35/90, tau_t = wb/w1 = (1 - tau_1 tau_2)/(1 - tau_2) = 47/72.
        t = gearkit.solve_train(example("trains", "seed_cvt_train.yaml"))
        self.assertEqual(t.ratio, Fraction(47, 72))
        self.assertIsInstance(t.ratio, Fraction)
        self.assertEqual(t.speed_ratios["23"], Fraction(-35, 90))
        self.assertEqual(t.dof, 2)  # the seed: 2 degrees of freedom before w5 = w1
        self.assertAlmostEqual(t.speeds_rad_s["b"], 1000 * 2 * math.pi / 60 * 47 / 72, places=9)

    def test_simple_planetary_by_willis(self):
        # Willis: (w_r - w_c)/(w_s - w_c) = -z_s/z_r = -24/60. Ring fixed: w_c/w_s = z_s/(z_s + z_r) = 2/7;
        # carrier fixed: w_r/w_s = -2/5.
        path = example("trains", "simple_planetary.yaml")
        self.assertEqual(gearkit.solve_train(path).ratio, Fraction(2, 7))
        t = gearkit.solve_train(path, fix="carrier", input="sun=3000 rpm", output="ring")
        self.assertEqual(t.ratio, Fraction(-2, 5))
        self.assertAlmostEqual(t.speeds_rad_s["ring"], -0.4 * 3000 * 2 * math.pi / 60, places=9)

    def test_power_flow_of_the_simple_planetary(self):
        # Ring fixed, sun driving: ideal T_c = -T_s w_s/w_c = -10 * 7/2 N*m. With losses the sun drives
        # the sun-planet-ring chain relative to the carrier, eta_0 = 0.98 * 0.99, i_0 = -z_r/z_s = -5/2:
        # eta = (1 + eta_0 |i_0|)/(1 + |i_0|) (Mueller, Die Umlaufgetriebe: the planetary's efficiency).
        t = gearkit.solve_train(example("trains", "simple_planetary.yaml"), input="sun=3000 rpm", fix="ring",
                                output="carrier", torque="sun=10 N*m")
        self.assertAlmostEqual(t.power_flow.torque_ideal_N_m["carrier"], -35.0, places=9)
        eta0 = Fraction(98, 100) * Fraction(99, 100)
        self.assertEqual(t.efficiency_exact, (1 + eta0 * Fraction(5, 2)) / (1 + Fraction(5, 2)))

    def test_same_numbers_as_the_cli(self):
        path = example("trains", "seed_two_epicyclic_stages.yaml")
        j = cli_json("train", path)
        t = gearkit.solve_train(path)
        self.assertEqual(str(t.ratio), j["ratio"]["exact"])
        self.assertEqual(float(t.ratio), j["ratio"]["value"])

    def test_bad_condition_raises_value_error(self):
        with self.assertRaisesRegex(ValueError, r"^argument 'fix': expected a member of the train"):
            gearkit.solve_train(example("trains", "simple_planetary.yaml"), fix="moon", input="sun")
        with self.assertRaisesRegex(ValueError, r"^argument 'input': .*unit"):
            gearkit.solve_train(example("trains", "simple_planetary.yaml"), fix="ring", input="sun=3000")


def rocker_angle(theta2, a=0.040, b=0.120, c=0.080, d=0.100):
    """The four-bar's rocker angle theta4 [rad] by hand (examples/mechanisms/four_bar.yaml): B is
    where the circle of radius b about A = a(cos, sin theta2) meets the circle of radius c about
    O4 = (d, 0); the drawing (rocker at 75 deg) is on the branch with B left of the line from A to O4."""
    ax, ay = a * np.cos(theta2), a * np.sin(theta2)
    ex, ey = d - ax, -ay
    f = np.hypot(ex, ey)
    along = (b * b - c * c + f * f) / (2 * f)
    h = np.sqrt(b * b - along * along)
    bx = ax + (along * ex - h * ey) / f  # left of the line from A to O4
    by = ay + (along * ey + h * ex) / f
    return np.arctan2(by, bx - d)


class MechanismTest(unittest.TestCase):
    def setUp(self):
        self.path = example("mechanisms", "four_bar.yaml")
        self.m = gearkit.Mechanism(self.path)

    def test_dof_of_the_four_bar(self):
        # Gruebler: 3 (4 - 1) - 2 * 4 = 1; the rank of Phi_q leaves 1 as well.
        d = self.m.dof()
        self.assertEqual(d.gruebler, 1)
        self.assertEqual(d.dof, 1)
        self.assertEqual(d.redundant, 0)

    def test_solve_against_the_loop_closure_by_hand(self):
        p = self.m.solve("30 deg")
        self.assertTrue(p.converged)
        self.assertAlmostEqual(p.outputs["theta4"][0], rocker_angle(30 * DEG), places=10)
        self.assertAlmostEqual(self.m.solve(30 * DEG).outputs["theta4"][0], p.outputs["theta4"][0], places=14)

    def test_sweep_arrays_against_the_loop_closure_by_hand(self):
        s = self.m.sweep("0 deg", "360 deg", "1 deg")
        self.assertEqual(len(s), 361)
        self.assertTrue(s.complete)
        self.assertEqual(s.q.shape, (361, len(self.m.coordinates)))
        self.assertTrue(s.q.flags.c_contiguous)
        np.testing.assert_allclose(s.input, np.arange(361) * DEG, rtol=0, atol=1e-12)
        theta4 = np.unwrap(s.output("theta4"))
        # to the solver's Newton tolerance (positions to about 1e-10 m over link lengths of 0.1 m)
        np.testing.assert_allclose(theta4, np.unwrap(rocker_angle(s.input)), rtol=0, atol=1e-8)
        # The rate by central differences of the hand angle at the crank speed 25 rad/s.
        h = 1e-6
        rate = 25 * (rocker_angle(s.input + h) - rocker_angle(s.input - h)) / (2 * h)
        np.testing.assert_allclose(s.rates[:, self.m.outputs.index("theta4")], rate, rtol=0, atol=1e-5)
        frame = s.to_dataframe()
        self.assertEqual(len(frame), 361)
        self.assertIn("theta4_rate", frame.columns)
        self.assertIn("coupler.theta", frame.columns)

    def test_default_range_and_cli_consistency(self):
        s = self.m.sweep()  # the file's range: 0..360 deg by 2 deg
        self.assertEqual(len(s), 181)
        rows = cli_json("kin", self.path, "--sweep", "0:360:2")["positions"]
        self.assertEqual(len(rows), len(s))
        k = self.m.outputs.index("theta4")
        for i in (0, 45, 90, 180):
            self.assertAlmostEqual(s.values[i, k] / DEG, rows[i]["outputs"]["theta4_deg"], places=9)

    def test_bad_file_raises_the_clis_message(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.yaml")
            with open(path, "w") as f:
                f.write("mechanism: x\nground: {O: [0, 0]}\nlinks:\n  a: {points: {O: [0, 0]}, angle: 3 kg}\n")
            with self.assertRaises(ValueError) as e:
                gearkit.Mechanism(path)
            self.assertEqual(str(e.exception), cli_error("kin", path))

    def test_bad_arguments(self):
        with self.assertRaisesRegex(ValueError, r"^argument 'driver': expected a driver of the mechanism \(theta2\)"):
            self.m.solve(0.0, driver="theta9")
        with self.assertRaisesRegex(ValueError, r"^argument 'at': expected an angle"):
            self.m.solve("3 mm")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]] + [a for a in sys.argv[1:] if a.startswith("-")])
