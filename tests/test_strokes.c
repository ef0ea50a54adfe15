/* The stroke count and interval laws (strokes.c): seeded draws against
 * their stated probability mass functions.
 *
 * Goodness of fit: Pearson's chi-square over 10 000 draws, bins with fewer
 * than 5 expected merged into their neighbour, rejected at significance
 * alpha = 0.001. The critical value comes from the Wilson-Hilferty
 * approximation chi2(df) ~ df (1 - 2/(9 df) + z sqrt(2/(9 df)))^3 with
 * z = 3.0902, the 0.999 quantile of the standard normal (within 0.5 % of
 * the tabulated values for df >= 3). With a fixed seed the outcome is fixed;
 * the test also shows it has power: the same draws are rejected against a
 * nearby wrong law. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>
#include <math.h>
#include <string.h>

#include "fulgur/engine.h"
#include "fg_rng.h"
#include "sound/strokes_internal.h"

#define DRAWS 10000
#define Z_999 3.0902

#define CHECK(cond, ...)            \
    do {                            \
        if (!(cond))                \
            fail_msg(__VA_ARGS__);  \
    } while (0)

/* The laws stated in strokes_internal.h, normalised over their cut
 * range: a log-series of parameter p on 1..kmax, and a Poisson of this
 * mean on 0..kmax. */
static double logseries_pmf(double p, int k, int kmax)
{
    double total = 0;
    for (int j = 1; j <= kmax; j++)
        total += pow(p, j) / j;
    return k < 1 || k > kmax ? 0.0 : pow(p, k) / k / total;
}

static double poisson_pmf(double mean, int k, int kmax)
{
    double total = 0;
    for (int j = 0; j <= kmax; j++)
        total += exp(j * log(mean) - mean - lgamma(j + 1.0));
    return k < 0 || k > kmax ? 0.0 : exp(k * log(mean) - mean - lgamma(k + 1.0)) / total;
}

static double chi2_critical(int df)
{
    double a = 2.0 / (9.0 * df);
    double b = 1.0 - a + Z_999 * sqrt(a);
    return df * b * b * b;
}

/* Pearson's statistic for observed counts against pmf over bins [0, n),
 * merging from the right while a bin expects fewer than 5. *df receives the
 * degrees of freedom (merged bins - 1). */
static double chi2(const unsigned *observed, const double *pmf, int n, int *df)
{
    double stat = 0, exp_acc = 0, obs_acc = 0;
    int bins = 0;
    for (int k = 0; k < n; k++) {
        exp_acc += DRAWS * pmf[k];
        obs_acc += observed[k];
        /* close the bin once it expects 5, or at the end if the rest of
         * the mass (what is left) is too small to stand alone */
        double rest = 0;
        for (int j = k + 1; j < n; j++)
            rest += DRAWS * pmf[j];
        if ((exp_acc >= 5 && rest >= 5) || k == n - 1) {
            stat += (obs_acc - exp_acc) * (obs_acc - exp_acc) / exp_acc;
            bins++;
            exp_acc = obs_acc = 0;
        }
    }
    *df = bins - 1;
    return stat;
}

typedef struct stroke_case {
    const char *name;
    uint64_t seed;
} stroke_case;

static const stroke_case cases[] = {{"seed 1", 1}, {"seed 2026", 2026}, {"seed 0xfeed", 0xfeed}};
#define N_CASES (sizeof cases / sizeof cases[0])

static void test_count_law(void **state)
{
    (void)state;
    double pmf[FG_MAX_STROKES], total = 0;
    for (int k = 1; k <= FG_MAX_STROKES; k++) {
        pmf[k - 1] = logseries_pmf(FG_STROKE_LOGSERIES_P, k, FG_MAX_STROKES);
        total += pmf[k - 1];
    }
    CHECK(fabs(total - 1.0) < 1e-12, "count pmf sums to %.15g", total);
    /* the stated figures: 45 % single, 4-6 strokes 15 %, > 10 strokes 3.8 % */
    double four_six = pmf[3] + pmf[4] + pmf[5], over_ten = 0;
    for (int k = 11; k <= FG_MAX_STROKES; k++)
        over_ten += pmf[k - 1];
    CHECK(fabs(pmf[0] - 0.45) < 0.01 && fabs(four_six - 0.15) < 0.01 &&
              fabs(over_ten - 0.038) < 0.002,
          "law figures: P(1) %.4f, P(4-6) %.4f, P(>10) %.4f", pmf[0], four_six, over_ten);

    for (size_t ci = 0; ci < N_CASES; ci++) {
        fg_rng rng;
        fg_rng_seed(&rng, cases[ci].seed);
        unsigned hist[FG_MAX_STROKES] = {0};
        for (int i = 0; i < DRAWS; i++) {
            uint32_t k = fg_strokes_draw_count(&rng);
            CHECK(k >= 1 && k <= FG_MAX_STROKES, "%s: drew %u strokes", cases[ci].name, k);
            hist[k - 1]++;
        }
        int df;
        double stat = chi2(hist, pmf, FG_MAX_STROKES, &df);
        CHECK(df >= 8, "%s: only %d degrees of freedom", cases[ci].name, df);
        CHECK(stat < chi2_critical(df), "%s: chi2 %.2f >= %.2f (df %d)", cases[ci].name, stat,
              chi2_critical(df), df);
        /* single strokes are the most frequent */
        for (int k = 1; k < FG_MAX_STROKES; k++)
            CHECK(hist[0] > hist[k], "%s: %u strokes drawn %u times, single %u", cases[ci].name,
                  k + 1, hist[k], hist[0]);

        /* power: a log-series with p = 0.8 instead of 0.85 is rejected */
        double wrong[FG_MAX_STROKES];
        for (int k = 1; k <= FG_MAX_STROKES; k++)
            wrong[k - 1] = logseries_pmf(0.8, k, FG_MAX_STROKES);
        double wstat = chi2(hist, wrong, FG_MAX_STROKES, &df);
        CHECK(wstat > chi2_critical(df), "%s: the wrong law passes (chi2 %.2f)", cases[ci].name,
              wstat);
    }
}

static void test_interval_law(void **state)
{
    (void)state;
    enum { KMAX = FG_STROKE_INTERVAL_MAX_K };
    double pmf[KMAX + 1], total = 0, mean_k = 0;
    for (int k = 0; k <= KMAX; k++) {
        pmf[k] = poisson_pmf(FG_STROKE_INTERVAL_POISSON_MEAN, k, KMAX);
        total += pmf[k];
        mean_k += k * pmf[k];
    }
    CHECK(fabs(total - 1.0) < 1e-12, "interval pmf sums to %.15g", total);
    /* each interval is 10 ms (1 + k + u), u uniform in [0, 1) */
    double want_mean = FG_STROKE_INTERVAL_UNIT_S * (1.5 + mean_k);
    CHECK(fabs(want_mean - 0.040) < 0.0005, "law mean %.5f s, not 40 ms", want_mean);

    for (size_t ci = 0; ci < N_CASES; ci++) {
        fg_rng rng;
        fg_rng_seed(&rng, cases[ci].seed);
        unsigned hist[KMAX + 1] = {0};
        double sum = 0, sum2 = 0;
        for (int i = 0; i < DRAWS; i++) {
            double t = fg_strokes_draw_interval_s(&rng);
            CHECK(t >= 0.010 && t < 0.240, "%s: interval %.6f s outside [10, 240) ms",
                  cases[ci].name, t);
            int k = (int)floor(t / FG_STROKE_INTERVAL_UNIT_S) - 1;
            if (k < 0)
                k = 0;
            if (k > KMAX)
                k = KMAX;
            hist[k]++;
            sum += t;
            sum2 += t * t;
        }
        int df;
        double stat = chi2(hist, pmf, KMAX + 1, &df);
        CHECK(df >= 5, "%s: only %d degrees of freedom", cases[ci].name, df);
        CHECK(stat < chi2_critical(df), "%s: chi2 %.2f >= %.2f (df %d)", cases[ci].name, stat,
              chi2_critical(df), df);
        /* the mean within 4 standard errors of the law's, and near 40 ms */
        double mean = sum / DRAWS, sd = sqrt(sum2 / DRAWS - mean * mean);
        CHECK(fabs(mean - want_mean) < 4 * sd / sqrt(DRAWS), "%s: mean %.5f s vs %.5f s",
              cases[ci].name, mean, want_mean);
        CHECK(fabs(mean - 0.040) < 0.001, "%s: mean interval %.5f s", cases[ci].name, mean);

        /* power: Poisson mean 3 instead of 2.5 is rejected */
        double wrong[KMAX + 1];
        for (int k = 0; k <= KMAX; k++)
            wrong[k] = poisson_pmf(3.0, k, KMAX);
        double wstat = chi2(hist, wrong, KMAX + 1, &df);
        CHECK(wstat > chi2_critical(df), "%s: the wrong law passes (chi2 %.2f)", cases[ci].name,
              wstat);
    }
}

/* Seeded draws repeat exactly; another seed gives another sequence. */
static void test_seeded_repeat(void **state)
{
    (void)state;
    enum { N = 1000 };
    static double a[2][N], b[2][N];
    const uint64_t seeds[2] = {42, 43};
    for (int s = 0; s < 2; s++) {
        fg_rng r1, r2;
        fg_rng_seed(&r1, seeds[s]);
        fg_rng_seed(&r2, seeds[s]);
        for (int i = 0; i < N; i++) {
            a[s][i] = fg_strokes_draw_count(&r1);
            a[s][i] += 1000.0 * fg_strokes_draw_interval_s(&r1);
            b[s][i] = fg_strokes_draw_count(&r2);
            b[s][i] += 1000.0 * fg_strokes_draw_interval_s(&r2);
        }
        CHECK(memcmp(a[s], b[s], sizeof a[s]) == 0, "seed %llu: draws differ",
              (unsigned long long)seeds[s]);
    }
    int same = 0;
    for (int i = 0; i < N; i++)
        same += a[0][i] == a[1][i];
    CHECK(same < N / 10, "seeds 42 and 43 agree on %d of %d draws", same, N);
}

/* The published schedule: first stroke at 0, intervals inside the law's
 * range, a count that follows the request, and answers for bad input. */
static void test_published_offsets(void **state)
{
    (void)state;
    double t[FG_MAX_STROKES + 1];
    fg_discharge d = {.strokes = FG_MAX_STROKES + 1};
    CHECK(fg_discharge_stroke_offsets(&d, t, FG_MAX_STROKES) == 0, "too many strokes");
    d = (fg_discharge){.continuous = 1, .seed = 3};
    t[0] = -1;
    CHECK(fg_discharge_stroke_offsets(&d, t, 1) == 1 && t[0] == 0.0, "continuous: one at 0");
    d = (fg_discharge){.strokes = 6, .seed = 9};
    t[2] = -1;
    CHECK(fg_discharge_stroke_offsets(&d, NULL, 0) == 6, "count without offsets");
    CHECK(fg_discharge_stroke_offsets(&d, t, 2) == 6 && t[2] == -1, "writes past max");
    CHECK(fg_discharge_stroke_offsets(&d, t, FG_MAX_STROKES) == 6 && t[0] == 0.0, "first at 0");
    for (int k = 1; k < 6; k++)
        CHECK(t[k] - t[k - 1] >= 0.010 && t[k] - t[k - 1] < 0.240, "interval %d: %g s", k,
              t[k] - t[k - 1]);
    uint32_t total = 0;
    for (uint64_t seed = 0; seed < 2000; seed++) {
        d = (fg_discharge){.seed = seed};
        total += fg_discharge_stroke_offsets(&d, NULL, 0);
    }
    CHECK(fabs(total / 2000.0 - 3.0) < 0.2, "drawn counts average %.2f, the law 3.0",
          total / 2000.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_count_law),
        cmocka_unit_test(test_interval_law),
        cmocka_unit_test(test_seeded_repeat),
        cmocka_unit_test(test_published_offsets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
