// Extraction throughput on one particle frame (bench/extract-throughput.sh drives it):
//  - Eq. 2.3 coarse graining onto bins of one mean diameter over the frame's whole domain, bin
//    kernel, as an extract stage runs it frame after frame: one extract::coarse::CoarseGrainer
//    called repeatedly (it keeps its cell arrays between calls), until at least --min-seconds
//    have been spent (and at least 5 calls after one untimed warm-up), median wall time per
//    call; contacts_per_s = contacts / that time. The one-shot extract::coarse::coarseGrain,
//    which allocates every array afresh, is timed the same way: contacts_per_s_fresh.
//  - The multi-pass MST (extract::structure::runMultiPassMst) with passes = 1 and passes = 4,
//    --mst-runs calls each, median wall times.
// Process CPU times are printed next to the wall times: on a loaded machine they show how much
// of a wall time was spent waiting for the CPU.
// The frame is read once before any timing: I/O is excluded. Single-threaded (extract has no
// threads); the script pins the process to one core.
//
// Usage: grainbridge_bench_extract FRAME.h5 [--min-seconds S] [--mst-runs N]
// Last two lines: `contacts_per_s = X` and `mst_100k_seconds = Y` (Y: one pass, median).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/data/ParticleFrame.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/CoarseGrainingKernel.hpp"
#include "extract/structure/MultiPassMst.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace coarse = grainbridge::extract::coarse;
namespace structure = grainbridge::extract::structure;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Process CPU time (user + system, page faults included): on a shared machine the wall time
// also holds the waits for the CPU, this does not.
double cpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: grainbridge_bench_extract FRAME.h5 [--min-seconds S] [--mst-runs N]\n");
  std::exit(2);
}

// Sink for results, so the optimiser cannot drop a call whose output is otherwise unused.
volatile double g_sink = 0.0;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) usage();
  std::filesystem::path framePath;
  double minSeconds = 2.0;
  int mstRuns = 3;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--min-seconds" && a + 1 < argc) {
      minSeconds = std::atof(argv[++a]);
    } else if (arg == "--mst-runs" && a + 1 < argc) {
      mstRuns = std::max(1, std::atoi(argv[++a]));
    } else if (!arg.empty() && arg[0] != '-' && framePath.empty()) {
      framePath = arg;
    } else {
      usage();
    }
  }
  if (framePath.empty()) usage();

  try {
    const Clock::time_point readStart = Clock::now();
    const grainbridge::core::data::ParticleFrame frame = grainbridge::core::io::readParticleFrame(framePath);
    const double readSeconds = secondsSince(readStart);
    const std::size_t particles = frame.size();
    const std::size_t contacts = frame.contacts.size();
    if (particles == 0) {
      std::fprintf(stderr, "frame %s holds no particles\n", framePath.c_str());
      return 1;
    }

    double meanDiameter = 0.0;
    for (const double r : frame.radius) meanDiameter += 2.0 * r;
    meanDiameter /= static_cast<double>(particles);
    const grainbridge::Vec3 length = frame.domain.hi - frame.domain.lo;
    std::array<int, 3> counts{};
    for (int axis = 0; axis < 3; ++axis) {
      counts[static_cast<std::size_t>(axis)] = std::max(1, static_cast<int>(std::lround(length[axis] / meanDiameter)));
    }
    const auto grid = grainbridge::core::grid::CellGrid::overDomain(frame.domain, counts);
    const auto kernel = coarse::CoarseGrainingKernel::bin();

    std::printf("frame: %s (read in %.3f s, not timed)\n", framePath.c_str(), readSeconds);
    std::printf("particles = %zu\n", particles);
    std::printf("contacts = %zu (coordination number 2 contacts / particles = %.3f; wall contacts %zu, not counted)\n",
                contacts, 2.0 * static_cast<double>(contacts) / static_cast<double>(particles),
                frame.wallContacts.size());
    std::printf("box = [%g %g %g] .. [%g %g %g], periodic %c%c%c, mean diameter %g\n", frame.domain.lo[0],
                frame.domain.lo[1], frame.domain.lo[2], frame.domain.hi[0], frame.domain.hi[1], frame.domain.hi[2],
                frame.domain.periodic[0] ? 'x' : '-', frame.domain.periodic[1] ? 'y' : '-',
                frame.domain.periodic[2] ? 'z' : '-', meanDiameter);
    std::printf("coarse graining: bin kernel, %d x %d x %d = %zu cells of one mean diameter\n", counts[0], counts[1],
                counts[2], grid.cellCount());

    // Coarse graining: one untimed warm-up call, then repeat until minSeconds (>= 5 calls).
    // call() returns the fields; drop() releases them, untimed, before the next call.
    const auto timeCoarseGraining = [&](const char* name, auto&& call, auto&& drop) {
      g_sink = g_sink + call().pressure[grid.cellCount() / 2];  // warm-up
      drop();
      std::vector<double> times, cpu;
      double total = 0.0;
      while (times.size() < 5 || total < minSeconds) {
        const double cpuStart = cpuSeconds();
        const Clock::time_point start = Clock::now();
        const coarse::CoarseFields& fields = call();
        const double t = secondsSince(start);
        cpu.push_back(cpuSeconds() - cpuStart);
        g_sink = g_sink + fields.pressure[fields.pressure.size() / 2];
        drop();
        times.push_back(t);
        total += t;
      }
      const double m = median(times);
      std::printf("%s = %.6g (median wall time of %zu calls, min %.6g, %.3g s in all; cpu median %.6g)\n", name, m,
                  times.size(), *std::min_element(times.begin(), times.end()), total, median(cpu));
      return m;
    };
    coarse::CoarseGrainer grainer;
    const double cgMedian = timeCoarseGraining(
        "coarse_grain_seconds", [&]() -> const coarse::CoarseFields& { return grainer(frame, grid, kernel); }, [] {});
    std::optional<coarse::CoarseFields> fresh;
    const double freshMedian = timeCoarseGraining(
        "coarse_grain_fresh_seconds",
        [&]() -> const coarse::CoarseFields& { return fresh.emplace(coarse::coarseGrain(frame, grid, kernel)); },
        [&] { fresh.reset(); });
    const double contactsPerSecond = static_cast<double>(contacts) / cgMedian;
    std::printf("particles_per_s = %.4g\n", static_cast<double>(particles) / cgMedian);
    std::printf("contacts_per_s_fresh = %.4g (one-shot coarseGrain, every array allocated afresh)\n",
                static_cast<double>(contacts) / freshMedian);

    // Multi-pass MST: passes = 1 and passes = 4, default options otherwise, mstRuns calls each.
    const auto timeMst = [&](int passes) {
      structure::MultiPassMstOptions options;
      options.passes = passes;
      std::vector<double> times, cpu;
      structure::MultiPassMstResult last;
      for (int r = 0; r < mstRuns; ++r) {
        const double cpuStart = cpuSeconds();
        const Clock::time_point start = Clock::now();
        last = structure::runMultiPassMst(frame, options);
        times.push_back(secondsSince(start));
        cpu.push_back(cpuSeconds() - cpuStart);
      }
      const double m = median(times);
      const structure::MstPass& final = last.passes.back();
      std::printf(
          "mst %d pass%s: %.4g s (median wall time of %d, min %.4g; cpu median %.4g), %zu candidate edges (cutoff "
          "%.4g), %zu forest trees, largest TCP %zu particles after pass %d\n",
          passes, passes == 1 ? "" : "es", m, mstRuns, *std::min_element(times.begin(), times.end()), median(cpu),
          last.candidateEdges, last.candidateCutoff, last.forestTrees, final.largestTree.particles, passes);
      g_sink = g_sink + static_cast<double>(final.edges.size());
      return m;
    };
    const double mst1 = timeMst(1);
    const double mst4 = timeMst(4);
    std::printf("mst_4_passes_seconds = %.4g\n", mst4);
    std::printf("contacts_per_s = %.4g\n", contactsPerSecond);
    std::printf("mst_100k_seconds = %.4g\n", mst1);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "grainbridge_bench_extract: %s\n", e.what());
    return 1;
  }
  return 0;
}
