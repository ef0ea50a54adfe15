/* fulgur run on a real JACK server: jackd with the dummy backend (no sound
 * card), started here under a name of its own and ended at the end. A
 * recording client of this test connects to whatever fulgur registers and
 * keeps what the server's process thread hands it. Checked:
 *   --audio jack:NAME  exit 0; the report names the device and its xruns;
 *                      the recording holds the scene's four sparks, 0.5 s
 *                      apart to within a block and a half, at the level
 *                      the lock-step WAV of the same scene has (+-3 dB)
 *                      (a spark may be lost with each xrun or late event
 *                      reported, the ones left still on the 0.5 s grid);
 *   --audio portaudio:system, the same through PortAudio's JACK device;
 *   no server of that name: exit 2 and the message.
 * Skipped (exit 77) with the reason when jackd is missing or cannot start.
 * usage: test_live_jack FULGUR SCENE.json */
#define _POSIX_C_SOURCE 200809L /* kill, setenv, nanosleep */
#include <math.h>
#include <setjmp.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>
#include <jack/jack.h>
#include <sndfile.h>

extern char **environ;

#define RATE_HZ 48000
#define PERIOD 256
#define MAX_SECONDS 12
#define SPARKS 4
#define SPARK_INTERVAL_S 0.5

static const char *fulgur, *scene;
static char server[64], tmpdir[64];
static pid_t jackd = -1;

/* the recorder */
static jack_client_t *client;
static jack_port_t *inputs[2];
static float *recorded[2];
static atomic_uint_fast64_t recorded_frames;
static atomic_bool recording;
/* begin_recording's handshake: a process cycle that finds recording off
 * answers the latest pause asked for, so none of its writes is under way */
static atomic_uint pause_asked, pause_seen;
/* the server's xruns while recording, as the recorder is told of them */
static atomic_long server_xruns;

static int count_xrun(void *arg)
{
    (void)arg;
    atomic_fetch_add(&server_xruns, 1);
    return 0;
}

static void quiet(const char *message)
{
    (void)message; /* libjack's "cannot connect" while the server starts */
}

static void sleep_ms(int ms)
{
    struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

static int record(jack_nframes_t n, void *arg)
{
    (void)arg;
    if (!atomic_load(&recording)) {
        atomic_store(&pause_seen, atomic_load(&pause_asked));
        return 0;
    }
    uint64_t at = atomic_load(&recorded_frames);
    if (at + n > (uint64_t)MAX_SECONDS * RATE_HZ)
        return 0;
    for (int ch = 0; ch < 2; ch++)
        memcpy(recorded[ch] + at, jack_port_get_buffer(inputs[ch], n), n * sizeof(float));
    atomic_store(&recorded_frames, at + n);
    return 0;
}

/* Starts jackd -d dummy; realtime first, then without (a sandbox may
 * refuse realtime scheduling). Returns 0 once a client can connect. */
static int start_server(char *why, size_t why_size)
{
    snprintf(server, sizeof server, "fulgur-test-%ld", (long)getpid());
    setenv("JACK_NO_AUDIO_RESERVATION", "1", 1); /* no D-Bus device reservation */
    setenv("JACK_NO_START_SERVER", "1", 1);
    jack_set_error_function(quiet);
    jack_set_info_function(quiet);
    for (int attempt = 0; attempt < 2; attempt++) {
        char log[128];
        snprintf(log, sizeof log, "%s/jackd.log", tmpdir);
        posix_spawn_file_actions_t fa;
        posix_spawn_file_actions_init(&fa);
        posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
        char rate[16], period[16];
        snprintf(rate, sizeof rate, "%d", RATE_HZ);
        snprintf(period, sizeof period, "%d", PERIOD);
        char *rt[] = {"jackd", "-n", server, "-d", "dummy", "-r", rate, "-p", period, NULL};
        char *no_rt[] = {"jackd", "--no-realtime", "-n", server, "-d", "dummy", "-r", rate, "-p", period, NULL};
        int e = posix_spawnp(&jackd, "jackd", &fa, NULL, attempt ? no_rt : rt, environ);
        posix_spawn_file_actions_destroy(&fa);
        if (e != 0) {
            snprintf(why, why_size, "jackd is not installed (Debian: jackd2)");
            jackd = -1;
            return -1;
        }
        for (int tries = 0; tries < 100; tries++) { /* 5 s */
            sleep_ms(50);
            jack_status_t status;
            client = jack_client_open("fulgur-test-recorder", JackNoStartServer | JackServerName,
                                      &status, server);
            if (client)
                return 0;
            int st;
            if (waitpid(jackd, &st, WNOHANG) == jackd)
                break; /* it gave up: try the other way */
        }
        kill(jackd, SIGTERM);
        waitpid(jackd, NULL, 0);
        jackd = -1;
        snprintf(why, why_size, "jackd -d dummy did not start (see its log: %s)", log);
    }
    return -1;
}

static void stop_server(void)
{
    if (client)
        jack_client_close(client);
    client = NULL;
    if (jackd > 0) {
        kill(jackd, SIGTERM);
        waitpid(jackd, NULL, 0);
    }
    jackd = -1;
}

/* Runs argv with extra environment, stdout to out_path; returns its exit
 * status. While it runs, connects every output port it registers to the
 * recorder. */
static int run_connected(char *const argv[], const char *out_path)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, out_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid;
    assert_int_equal(posix_spawn(&pid, argv[0], &fa, NULL, argv, environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    int connected = 0, status = 0;
    for (;;) {
        if (waitpid(pid, &status, WNOHANG) == pid)
            break;
        if (connected < 2) {
            const char **ports = jack_get_ports(client, NULL, JACK_DEFAULT_AUDIO_TYPE, JackPortIsOutput);
            for (int i = 0; ports && ports[i]; i++) {
                if (strncmp(ports[i], "system:", 7) == 0 ||
                    strncmp(ports[i], "fulgur-test-recorder:", 21) == 0 || connected >= 2)
                    continue;
                if (jack_connect(client, ports[i], jack_port_name(inputs[connected])) == 0)
                    connected++;
            }
            if (ports)
                jack_free((void *)ports);
        }
        sleep_ms(2);
    }
    assert_int_equal(connected, 2);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static void begin_recording(void)
{
    atomic_store(&recording, false);
    unsigned asked = atomic_fetch_add(&pause_asked, 1) + 1;
    for (int ms = 0; atomic_load(&pause_seen) != asked; ms++) {
        assert_true(ms < 2000); /* the server runs a cycle every 5.3 ms */
        sleep_ms(1);
    }
    atomic_store(&recorded_frames, 0);
    atomic_store(&server_xruns, 0);
    memset(recorded[0], 0, sizeof(float) * MAX_SECONDS * RATE_HZ);
    memset(recorded[1], 0, sizeof(float) * MAX_SECONDS * RATE_HZ);
    atomic_store(&recording, true);
}

static double peak_of(float *const *planes, size_t frames)
{
    double m = 0;
    for (size_t i = 0; i < frames; i++)
        m = fmax(m, fmax(fabs(planes[0][i]), fabs(planes[1][i])));
    return m;
}

/* The frames at which each burst starts: above a tenth of the peak after
 * 0.2 s below it. */
static int onsets(float *const *planes, size_t frames, double peak, size_t *at, int max)
{
    int n = 0;
    size_t quiet = (size_t)(0.2 * RATE_HZ), since = quiet;
    for (size_t i = 0; i < frames; i++) {
        double v = fmax(fabs(planes[0][i]), fabs(planes[1][i]));
        if (v > 0.1 * peak) {
            if (since >= quiet && n < max)
                at[n++] = i;
            since = 0;
        } else {
            since++;
        }
    }
    return n;
}

/* The lock-step WAV's peak: what the live output should reach. */
static double reference_peak(void)
{
    char wav[128], arg[160], report[128];
    snprintf(wav, sizeof wav, "%s/reference.wav", tmpdir);
    snprintf(arg, sizeof arg, "wav:%s", wav);
    snprintf(report, sizeof report, "%s/reference.json", tmpdir);
    char *argv[] = {(char *)fulgur, "run", (char *)scene, "--audio", arg, "--report", report, NULL};
    pid_t pid;
    int status;
    assert_int_equal(posix_spawn(&pid, fulgur, NULL, NULL, argv, environ), 0);
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    SF_INFO info = {0};
    SNDFILE *f = sf_open(wav, SFM_READ, &info);
    assert_non_null(f);
    float *buf = malloc(sizeof(float) * (size_t)info.frames * 2);
    assert_int_equal(sf_readf_float(f, buf, info.frames), info.frames);
    sf_close(f);
    double m = 0;
    for (sf_count_t i = 0; i < info.frames * 2; i++)
        m = fmax(m, fabs(buf[i]));
    free(buf);
    return m;
}

/* The xruns the report gives (it must name the device and give them), and
 * its late events (posts that came after their sound began). */
static long reported_xruns(const char *report_path, long *late_events)
{
    FILE *r = fopen(report_path, "r");
    assert_non_null(r);
    char text[65536];
    size_t len = fread(text, 1, sizeof text - 1, r);
    fclose(r);
    text[len] = 0;
    char *xruns = strstr(text, "\"xruns\":");
    assert_non_null(strstr(text, "\"live\":"));
    assert_non_null(xruns);
    char *late = strstr(text, "\"late\":");
    assert_non_null(late);
    char *events = strstr(late, "\"events\":");
    assert_non_null(events);
    *late_events = strtol(events + 9, NULL, 10);
    return strtol(xruns + 8, NULL, 10);
}

/* Every spark, on time, at the WAV's level. An xrun loses a period of the
 * output, and a spark (a few milliseconds) can vanish with it; so can a
 * spark posted after its sound began (the run's thread held off the CPU:
 * under ThreadSanitizer with both cores busy 10 of 40 runs lost one,
 * and its report counted 2 late events, the spark's two ears). With n
 * xruns (the more of fulgur's report and the server's own count, as the
 * recorder was told) and m late events up to n + m sparks may be missing,
 * and the onsets left are a whole number of intervals apart. Without
 * either all four must be there. */
static void check_recording(const char *what, const char *report_path)
{
    long late;
    long reported = reported_xruns(report_path, &late), seen = atomic_load(&server_xruns);
    long xruns = reported > seen ? reported : seen;
    size_t frames = (size_t)atomic_load(&recorded_frames);
    double peak = peak_of(recorded, frames), want = reference_peak();
    size_t at[SPARKS + 2];
    int n = onsets(recorded, frames, peak, at, SPARKS + 2);
    printf("%s: recorded %.2f s, peak %.4g Pa (lock-step WAV %.4g Pa, %+.2f dB), %d onsets, "
           "%ld xruns (report %ld, server %ld), %ld late events\n", what, (double)frames / RATE_HZ,
           peak, want, 20 * log10(peak / want), n, xruns, reported, seen, late);
    for (int i = 0; i < n; i++)
        printf("  onset at %.4f s of the recording\n", (double)at[i] / RATE_HZ);
    assert_true(peak > 0);
    assert_true(fabs(20 * log10(peak / want)) < 3);
    const long may_miss = xruns + late;
    assert_true(n <= SPARKS && n >= SPARKS - (may_miss < SPARKS - 1 ? may_miss : SPARKS - 1));
    for (int i = 1; i < n; i++) {
        double gap_s = (double)(at[i] - at[i - 1]) / RATE_HZ;
        long intervals = lround(gap_s / SPARK_INTERVAL_S);
        printf("  onset %d: %.4f s after the one before\n", i, gap_s);
        assert_true(intervals >= 1);
        if (n == SPARKS)
            assert_int_equal(intervals, 1);
        assert_true(fabs(gap_s - intervals * SPARK_INTERVAL_S) < 1.5 * PERIOD / (double)RATE_HZ);
    }
}

static void test_jack(void **state)
{
    (void)state;
    char target[96], report[128];
    snprintf(target, sizeof target, "jack:%s", server);
    snprintf(report, sizeof report, "%s/jack.json", tmpdir);
    begin_recording();
    char *argv[] = {(char *)fulgur, "run", (char *)scene, "--audio", target, NULL};
    assert_int_equal(run_connected(argv, report), 0);
    check_recording("--audio jack", report);
}

static void test_portaudio_through_jack(void **state)
{
    (void)state;
    char report[128];
    snprintf(report, sizeof report, "%s/portaudio.json", tmpdir);
    setenv("JACK_DEFAULT_SERVER", server, 1);
    begin_recording();
    char *argv[] = {(char *)fulgur, "run", (char *)scene, "--audio", "portaudio:system", NULL};
    int rc = run_connected(argv, report);
    unsetenv("JACK_DEFAULT_SERVER");
    assert_int_equal(rc, 0);
    check_recording("--audio portaudio:system", report);
}

static void test_no_server(void **state)
{
    (void)state;
    char err[128];
    snprintf(err, sizeof err, "%s/none.err", tmpdir);
    char *argv[] = {(char *)fulgur, "run", (char *)scene, "--audio", "jack:fulgur-no-such-server", NULL};
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid;
    int status;
    assert_int_equal(posix_spawn(&pid, fulgur, &fa, NULL, argv, environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 2);
    FILE *f = fopen(err, "r");
    char line[512] = "";
    assert_non_null(f);
    assert_non_null(fgets(line, sizeof line, f));
    fclose(f);
    printf("no server: %s", line);
    assert_non_null(strstr(line, "no JACK server \"fulgur-no-such-server\" is running"));
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: test_live_jack FULGUR SCENE.json\n");
        return 2;
    }
    fulgur = argv[1];
    scene = argv[2];
    snprintf(tmpdir, sizeof tmpdir, "/tmp/fulgur-jack-XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    char why[256];
    if (start_server(why, sizeof why) != 0) {
        printf("SKIPPED: %s\n", why);
        return 77;
    }
    recorded[0] = calloc((size_t)MAX_SECONDS * RATE_HZ, sizeof(float));
    recorded[1] = calloc((size_t)MAX_SECONDS * RATE_HZ, sizeof(float));
    inputs[0] = jack_port_register(client, "in_left", JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0);
    inputs[1] = jack_port_register(client, "in_right", JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0);
    if (!recorded[0] || !recorded[1] || !inputs[0] || !inputs[1] ||
        jack_set_process_callback(client, record, NULL) != 0 ||
        jack_set_xrun_callback(client, count_xrun, NULL) != 0 || jack_activate(client) != 0) {
        stop_server();
        return 1;
    }
    printf("jackd -d dummy as \"%s\", %u Hz, %u frames\n", server, jack_get_sample_rate(client),
           jack_get_buffer_size(client));
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_jack),
        cmocka_unit_test(test_portaudio_through_jack),
        cmocka_unit_test(test_no_server),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    stop_server();
    free(recorded[0]);
    free(recorded[1]);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    if (system(cmd) != 0)
        rc = rc ? rc : 1;
    return rc;
}
