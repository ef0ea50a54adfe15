/* Absorption of sound by the atmosphere, ISO 9613-1:1993 (eqs. 3-5 and
 * annex B): the pure-tone attenuation coefficient from temperature,
 * relative humidity and pressure. */
#ifndef FULGUR_AIR_ABSORPTION_INTERNAL_H
#define FULGUR_AIR_ABSORPTION_INTERNAL_H

/* The still air a sound crosses. The standard covers -20..50 C, 10..100 %
 * RH (below about 0.05 % molar water vapour it is less accurate) and
 * pressures up to 200 kPa. */
typedef struct fg_air {
    double temperature_c;
    double humidity_pct;  /* relative humidity, 0..100 */
    double pressure_kpa;
} fg_air;

/* 20 C, 70 % RH, 101.325 kPa. */
#define FG_AIR_DEFAULT ((fg_air){20.0, 70.0, 101.325})

/* Molar concentration of water vapour h, percent (annex B, eq. B.1). */
double fg_air_water_vapour_pct(const fg_air *air);

/* Relaxation frequencies of oxygen and nitrogen, Hz (eqs. 3 and 4). */
double fg_air_relax_oxygen_hz(const fg_air *air);
double fg_air_relax_nitrogen_hz(const fg_air *air);

/* Attenuation coefficient alpha, dB per metre, at frequency f_hz (eq. 5).
 * A pure tone loses alpha * d decibels over d metres. */
double fg_air_alpha_db_m(const fg_air *air, double f_hz);

#endif
