/* Cameras for the projective tests (tests/proj_cases.h). */
#include <math.h>

#include "proj_cases.h"

static void rotation(const double q[4], double Q[3][3])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    Q[0][0] = 1 - 2 * (y * y + z * z); Q[0][1] = 2 * (x * y - w * z); Q[0][2] = 2 * (x * z + w * y);
    Q[1][0] = 2 * (x * y + w * z); Q[1][1] = 1 - 2 * (x * x + z * z); Q[1][2] = 2 * (y * z - w * x);
    Q[2][0] = 2 * (x * z - w * y); Q[2][1] = 2 * (y * z + w * x); Q[2][2] = 1 - 2 * (x * x + y * y);
}

void tc_camera(double P[4][4], double F, double asp, double n, double f, const double q[4], const double T[3])
{
    double Pm[4][4] = {{0}}, V[4][4] = {{0}}, Q[3][3];
    int i, j, k;
    Pm[0][0] = F / asp;
    Pm[1][1] = F;
    Pm[2][2] = (f + n) / (n - f);
    Pm[2][3] = 2 * f * n / (n - f);
    Pm[3][2] = -1;
    rotation(q, Q);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++)
            V[i][j] = Q[i][j];
        V[i][3] = T[i];
    }
    V[3][3] = 1;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s = 0;
            for (k = 0; k < 4; k++)
                s += Pm[i][k] * V[k][j];
            P[i][j] = s;
        }
}

void tc_to_world(const double q[4], const double T[3], const double v[3], double c[3])
{
    double Q[3][3], d[3];
    int j;
    rotation(q, Q);
    for (j = 0; j < 3; j++)
        d[j] = v[j] - T[j];
    for (j = 0; j < 3; j++)
        c[j] = Q[0][j] * d[0] + Q[1][j] * d[1] + Q[2][j] * d[2];
}

double tc_scaled(xu_rng *g, double m, int lo, int hi)
{
    int e = xu_rng_int(g, lo, hi);
    return ldexp(m, e);
}

void tc_random_camera(xu_rng *g, double P[4][4], double q[4], double T[3], double *n)
{
    double nq = 0, F, f;
    int j;
    for (j = 0; j < 4; j++) {
        q[j] = 2 * xu_rng_unit(g) - 1;
        nq += q[j] * q[j];
    }
    nq = sqrt(nq);
    for (j = 0; j < 4; j++)
        q[j] /= nq;
    for (j = 0; j < 3; j++)
        T[j] = tc_scaled(g, 2 * xu_rng_unit(g) - 1, -2, 12);
    F = tc_scaled(g, 1 + xu_rng_unit(g), -7, 6);
    *n = ldexp(1.0, xu_rng_int(g, -8, 2));
    f = *n * ldexp(1.0, xu_rng_int(g, 2, 20));
    tc_camera(P, F, 0.5 + 2 * xu_rng_unit(g), *n, f, q, T);
}
