#include <math.h>

#include "air_absorption_internal.h"

#define T0_K 293.15   /* reference air temperature */
#define T01_K 273.16  /* triple-point isotherm */
#define PR_KPA 101.325

static double kelvin(const fg_air *air)
{
    return air->temperature_c + 273.15;
}

double fg_air_water_vapour_pct(const fg_air *air)
{
    double c = -6.8346 * pow(T01_K / kelvin(air), 1.261) + 4.6151;
    double psat_over_pr = pow(10.0, c);
    return air->humidity_pct * psat_over_pr / (air->pressure_kpa / PR_KPA);
}

double fg_air_relax_oxygen_hz(const fg_air *air)
{
    double h = fg_air_water_vapour_pct(air);
    return air->pressure_kpa / PR_KPA * (24.0 + 4.04e4 * h * (0.02 + h) / (0.391 + h));
}

double fg_air_relax_nitrogen_hz(const fg_air *air)
{
    double h = fg_air_water_vapour_pct(air);
    double tr = kelvin(air) / T0_K;
    return air->pressure_kpa / PR_KPA / sqrt(tr) *
           (9.0 + 280.0 * h * exp(-4.170 * (pow(tr, -1.0 / 3.0) - 1.0)));
}

double fg_air_alpha_db_m(const fg_air *air, double f_hz)
{
    double t = kelvin(air), tr = t / T0_K, f2 = f_hz * f_hz;
    double fro = fg_air_relax_oxygen_hz(air), frn = fg_air_relax_nitrogen_hz(air);
    double classical = 1.84e-11 * (PR_KPA / air->pressure_kpa) * sqrt(tr);
    double oxygen = 0.01275 * exp(-2239.1 / t) / (fro + f2 / fro);
    double nitrogen = 0.1068 * exp(-3352.0 / t) / (frn + f2 / frn);
    return 8.686 * f2 * (classical + pow(tr, -2.5) * (oxygen + nitrogen));
}
