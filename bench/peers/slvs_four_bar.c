/* The peer of bench_kin_process: SolveSpace's solver (libslvs, Debian libslvs1-dev) as a user of
 * it would drive it from C, solving the benchmark four-bar (crank 40, coupler 120, rocker 80,
 * ground 100 mm) for positions only (libslvs has no velocity analysis) at N crank angles over
 * one turn, each from the previous solution, and printing each position as a CSV row
 * (crank angle, B x, B y) - the positions-only counterpart of `gearkit kin --format csv`.
 * usage: slvs_four_bar N */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h> /* slvs.h uses memset without including it */

#include <slvs.h>

int main(int argc, char** argv) {
  const int n = argc > 1 ? atoi(argv[1]) : 36000;
  const double a = 40, b = 120, c = 80, d = 100;
  Slvs_Param param[16];
  Slvs_Entity entity[8];
  Slvs_Constraint constraint[2];
  const Slvs_hGroup g1 = 1, g2 = 2;
  int np = 0, ne = 0;
  double qw, qx, qy, qz;
  param[np++] = Slvs_MakeParam(1, g1, 0.0);
  param[np++] = Slvs_MakeParam(2, g1, 0.0);
  param[np++] = Slvs_MakeParam(3, g1, 0.0);
  entity[ne++] = Slvs_MakePoint3d(101, g1, 1, 2, 3);
  Slvs_MakeQuaternion(1, 0, 0, 0, 1, 0, &qw, &qx, &qy, &qz);
  param[np++] = Slvs_MakeParam(4, g1, qw);
  param[np++] = Slvs_MakeParam(5, g1, qx);
  param[np++] = Slvs_MakeParam(6, g1, qy);
  param[np++] = Slvs_MakeParam(7, g1, qz);
  entity[ne++] = Slvs_MakeNormal3d(102, g1, 4, 5, 6, 7);
  entity[ne++] = Slvs_MakeWorkplane(200, g1, 101, 102);
  param[np++] = Slvs_MakeParam(11, g1, d); /* O4 */
  param[np++] = Slvs_MakeParam(12, g1, 0.0);
  entity[ne++] = Slvs_MakePoint2d(301, g1, 200, 11, 12);
  param[np++] = Slvs_MakeParam(13, g1, a); /* A, moved to the crank angle before each solve */
  param[np++] = Slvs_MakeParam(14, g1, 0.0);
  entity[ne++] = Slvs_MakePoint2d(302, g1, 200, 13, 14);
  param[np++] = Slvs_MakeParam(15, g2, 136.7); /* B, free; starts near the drawn branch */
  param[np++] = Slvs_MakeParam(16, g2, 71.1);
  entity[ne++] = Slvs_MakePoint2d(303, g2, 200, 15, 16);
  constraint[0] = Slvs_MakeConstraint(1, g2, SLVS_C_PT_PT_DISTANCE, 200, b, 302, 303, 0, 0);
  constraint[1] = Slvs_MakeConstraint(2, g2, SLVS_C_PT_PT_DISTANCE, 200, c, 301, 303, 0, 0);
  Slvs_hConstraint failed[2];
  Slvs_System sys = {0};
  sys.param = param;
  sys.params = np;
  sys.entity = entity;
  sys.entities = ne;
  sys.constraint = constraint;
  sys.constraints = 2;
  sys.failed = failed;
  sys.faileds = 2;
  printf("theta2 [deg],Bx [mm],By [mm]\n");
  for (int k = 0; k < n; ++k) {
    const double theta = 2 * M_PI * k / n;
    param[9].val = a * cos(theta);
    param[10].val = a * sin(theta);
    Slvs_Solve(&sys, g2);
    if (sys.result != SLVS_RESULT_OKAY) {
      fprintf(stderr, "slvs_four_bar: no convergence at %g deg\n", theta * 180 / M_PI);
      return 1;
    }
    printf("%.4f,%.4f,%.4f\n", theta * 180 / M_PI, param[11].val, param[12].val);
  }
  return 0;
}
