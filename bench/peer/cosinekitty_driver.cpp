// The peer of the whole-process benchmark (bench/whole_process.c): a
// command-line driver of cosinekitty/thunder (MIT, C++), written here for
// measuring only and compiled against a clone of the peer outside this
// tree (build_cosinekitty.sh); none of the peer's code is in fulgur.
//
// usage: peer SEGMENTS OUT.wav [NODES.txt]
// Generates the peer's fractal bolt of SEGMENTS segments (its defaults:
// 3 km high, 1 km radius, seed 0), hears it with two ears 0.2 m apart
// 50 m from the strike point at 1.7 m, renders the peer's stereo thunder
// at 44.1 kHz and writes it as its own float WAV writer does. Prints
//   seconds=S synthesis_cpu_s=C
// (S: the sound's length; C: Thunder::start + renderAudio, this process's
// CPU time). NODES.txt gets the bolt as "x y z" lines, top first (the
// peer's segments form one chain), and the ears' midpoint as the last
// line, so that fulgur renders the same bolt from the same place.
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "lightning.hpp"
#include "wavefile.hpp"

static double cpu_s()
{
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: peer SEGMENTS OUT.wav [NODES.txt]\n");
        return 2;
    }
    const long segments = std::atol(argv[1]);
    if (segments < 1 || segments > 10000000) {
        std::fprintf(stderr, "peer: SEGMENTS must be 1..10000000\n");
        return 2;
    }
    const int rate = 44100;
    Sapphire::LightningBolt bolt(segments);
    bolt.generate();
    const Sapphire::BoltPoint strike = bolt.segments().back().b;
    const Sapphire::BoltPointList ears{
        Sapphire::BoltPoint{strike.x + 50.0, strike.y + 0.1, 1.7},
        Sapphire::BoltPoint{strike.x + 50.0, strike.y - 0.1, 1.7}};
    Sapphire::Thunder thunder{ears, static_cast<std::size_t>(segments)};
    const double c0 = cpu_s();
    thunder.start(bolt);
    Sapphire::AudioBuffer audio = thunder.renderAudio(rate);
    const double synthesis = cpu_s() - c0;
    std::vector<float> samples = audio.buffer();
    Sapphire::ScaledWaveFileWriter wav;
    if (!wav.Open(argv[2], rate, 2)) {
        std::fprintf(stderr, "peer: cannot open %s\n", argv[2]);
        return 1;
    }
    wav.WriteBuffer(samples);
    wav.Close();
    if (argc > 3) {
        FILE *f = std::fopen(argv[3], "w");
        if (!f)
            return 1;
        std::fprintf(f, "%.17g %.17g %.17g\n", bolt.segments().front().a.x,
                     bolt.segments().front().a.y, bolt.segments().front().a.z);
        for (const Sapphire::BoltSegment &s : bolt.segments())
            std::fprintf(f, "%.17g %.17g %.17g\n", s.b.x, s.b.y, s.b.z);
        std::fprintf(f, "%.17g %.17g %.17g\n", strike.x + 50.0, strike.y, 1.7);
        std::fclose(f);
    }
    std::printf("seconds=%.6f synthesis_cpu_s=%.6f\n", (double)audio.frames() / rate, synthesis);
    return 0;
}
