// Shell kernel throughput: one Belytschko-Tsay pass (mid-step strains, 5 plane-stress points,
// resultants, hourglass control, forces and moments, energies, stable step) plus the ordered
// nodal gather of forces and moments, on a mildly distorted and warped 400 x 250 plate (100k
// elements; 40 x 250 = 10k fits in cache). Reports ns per element-cycle. The thread count is
// the first argument (omp_set_num_threads), so one run gives 1 and 2 threads:
//   build/release/bench/crumple_bench --benchmark_filter=Shell --benchmark_min_time=1
#include <benchmark/benchmark.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <vector>

#include "domain/blocks.hpp"
#include "elements/shell.hpp"
#include "materials/materials.hpp"

namespace {

using namespace crumple;

struct Plate {
  domain::ShellBlock blk;
  domain::NodeVector x, v, w;
  std::vector<double> slots, f, m;
  // Gather plan: per node, its element corners in element order (as the solver's plan).
  std::vector<int32_t> ptr, corner;
};

// `ply`: the points' material angles through the thickness (*SECTION_SHELL ICOMP 1); empty: 0.
Plate plate(int nx, int ny, const materials::Law& law, int nip, int ihq,
            const std::vector<double>& ply = {}) {
  Plate p;
  const auto node = [&](int i, int j) { return int32_t(i + (nx + 1) * j); };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      // A mild in-plane distortion and warping so no shortcut of a flat grid applies.
      p.x.push_back(i + 0.05 * std::sin(j));
      p.x.push_back(j + 0.05 * std::cos(i));
      p.x.push_back(0.02 * std::sin(i + 2 * j));
    }
  auto& b = p.blk;
  b.law = law;
  b.rho0 = 7.85e-6;
  b.nip = nip;
  b.ihq = ihq;
  b.qm = 0.1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      b.conn.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});
  b.corner_thickness.assign(b.conn.size(), {0.1, 0.1, 0.1, 0.1});
  b.ply = ply;
  b.elem.resize(b.conn.size());
  std::iota(b.elem.begin(), b.elem.end(), 0);
  b.elem_id.assign(b.elem.begin(), b.elem.end());
  elements::resizeShellBlock(b, b.size());
  p.slots.assign(3 * 8 * b.size(), 0.0);
  std::vector<double> dt_e;
  elements::initializeShells(b, p.x, p.slots.data(), dt_e);
  // A stretching, shearing, bending velocity field large enough to yield the plastic law.
  const std::size_t nn = p.x.size() / 3;
  p.v.resize(3 * nn);
  p.w.resize(3 * nn);
  for (std::size_t k = 0; k < nn; ++k) {
    const double* q = &p.x[3 * k];
    p.v[3 * k] = 2.0 * q[1] - 1.0 * q[0];
    p.v[3 * k + 1] = 0.5 * q[0];
    p.v[3 * k + 2] = 0.1 * (q[0] + q[1]);
    p.w[3 * k] = 0.3 * q[1];
    p.w[3 * k + 1] = -0.2 * q[0];
    p.w[3 * k + 2] = 0.0;
  }
  p.ptr.assign(nn + 1, 0);
  for (const auto& c : b.conn)
    for (int a = 0; a < 4; ++a) ++p.ptr[std::size_t(c[a]) + 1];
  std::partial_sum(p.ptr.begin(), p.ptr.end(), p.ptr.begin());
  p.corner.resize(std::size_t(p.ptr.back()));
  std::vector<int32_t> fill(p.ptr.begin(), p.ptr.end() - 1);
  for (std::size_t e = 0; e < b.size(); ++e)
    for (int a = 0; a < 4; ++a)
      p.corner[std::size_t(fill[std::size_t(b.conn[e][a])]++)] = int32_t(8 * e + a);
  p.f.resize(3 * nn);
  p.m.resize(3 * nn);
  return p;
}

void runShell(benchmark::State& state, const materials::Law& law, int ihq, int warmup = 0,
              const std::vector<double>& ply = {}) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  Plate p = plate(static_cast<int>(state.range(1)), 250, law, 5, ihq, ply);
  const double dt = 1e-5;
  const std::size_t nn = p.x.size() / 3;
  const bool gather = state.range(2) != 0;
  // Cycles before timing: load the points up to (and past) yield.
  for (int k = 0; k < warmup; ++k)
    elements::computeShellForces(p.blk, p.x, p.v, p.w, dt, p.slots.data());
  for (auto _ : state) {
    elements::computeShellForces(p.blk, p.x, p.v, p.w, dt, p.slots.data());
    if (gather) {
#pragma omp parallel for schedule(static)
      for (std::size_t n = 0; n < nn; ++n) {
        double sf[3] = {0, 0, 0}, sm[3] = {0, 0, 0};
        for (int32_t k = p.ptr[n]; k < p.ptr[n + 1]; ++k) {
          const double* fs = &p.slots[3 * std::size_t(p.corner[std::size_t(k)])];
          const double* ms = fs + 12;  // the moment slot of the same corner
          for (int c = 0; c < 3; ++c) {
            sf[c] += fs[c];
            sm[c] += ms[c];
          }
        }
        for (int c = 0; c < 3; ++c) {
          p.f[3 * n + c] = sf[c];
          p.m[3 * n + c] = sm[c];
        }
      }
    }
    benchmark::DoNotOptimize(p.f.data());
    benchmark::DoNotOptimize(p.slots.data());
  }
  const double elems = double(p.blk.size());
  state.counters["ns_per_element_cycle"] =
      benchmark::Counter(elems * double(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["elements"] = elems;
}

// Bilinear *MAT_024 from its deck parameters.
materials::Law bilinear024(double sigy, double etan) {
  materials::PiecewiseLinear::Params p;
  p.E = 210.0;
  p.nu = 0.3;
  p.sigy = sigy;
  p.etan = etan;
  return materials::makeLaw(p, {}, "");
}

materials::Law plastic024() {
  return bilinear024(0.001, 1.0);  // yields at once under the imposed strain rate
}

// Crash-like plasticity: SIGY 0.3 GPa, and strain increments of about 1e-5 a step (strain
// rates of about 1000/s), so that every point, once past yield, overshoots the yield surface by
// about 1 % a step. Timed after 300 cycles, when all points are plastic.
void ShellPlastic024Crash(benchmark::State& s) {
  runShell(s, bilinear024(0.3, 1.0), 1, 300);
}
// *MAT_024 with a yield curve (LCSS), and with LCSS naming a rate table of three such curves
// at 0.1, 1 and 10 per time unit (the plate's strain rates lie near 1, between the last two):
// the cost of the table is the rate, a lookup of the two neighbouring curves and their blend at
// each point of the return (materials/rate.hpp). Crash-like, as ShellPlastic024Crash.
const std::vector<double> kEpsA{0.0, 0.05, 0.2}, kSigA{0.3, 0.4, 0.46};
const std::vector<double> kEpsB{0.0, 0.1}, kSigB{0.33, 0.45};
const std::vector<double> kEpsC{0.0, 0.02, 0.3}, kSigC{0.36, 0.4, 0.52};
const std::vector<double> kRates{0.1, 1.0, 10.0};
const std::vector<int32_t> kTableCurves{0, 1, 2};

materials::Law curve024(bool table, bool viscoplastic = false) {
  materials::PiecewiseLinear::Params p;
  p.E = 210.0;
  p.nu = 0.3;
  (table ? p.table : p.lcss) = 0;
  p.viscoplastic = viscoplastic;
  const materials::CurveAt curves(
      [](int32_t i) -> materials::CurveData {
        if (i == 1) return {2, kEpsB, kSigB};
        if (i == 2) return {3, kEpsC, kSigC};
        return {1, kEpsA, kSigA};
      },
      [](int32_t) -> materials::TableData {
        return {5, kRates, kTableCurves};
      });
  return materials::makeLaw(p, curves, "");
}
void ShellPlastic024CurveCrash(benchmark::State& s) {
  runShell(s, curve024(false), 1, 300);
}
void ShellPlastic024RateTableCrash(benchmark::State& s) {
  runShell(s, curve024(true), 1, 300);
}
// VP = 1 (viscoplastic): the same table at the plastic strain rate, inside the return
// (return_mapping.hpp, viscoplasticFlow): Newton on the rate as well as the curve.
void ShellPlastic024RateTableViscoplasticCrash(benchmark::State& s) {
  runShell(s, curve024(true, true), 1, 300);
}
// *MAT_054 (enhanced composite damage, Chang-Chang) on a [0/45/90/-45/0] lay-up, one ply per
// point through the thickness (*SECTION_SHELL ICOMP 1): a carbon-epoxy ply (GPa), with
// strengths too high for the imposed strains to fail it, so that every pass evaluates the
// intact ply's stress and the four failure criteria.
materials::Law composite054() {
  materials::EnhancedComposite::Params p;
  p.ea = 130.0;
  p.eb = p.ec = 10.0;
  p.prba = 0.02;
  p.prca = p.prcb = 0.3;
  p.gab = p.gca = 5.0;
  p.gbc = 3.0;
  p.xt = p.xc = p.yt = p.yc = p.sc = 100.0;
  return materials::makeLaw(p, {}, "");
}
void ShellComposite054(benchmark::State& s) {
  const double d = std::numbers::pi / 180.0;
  runShell(s, composite054(), 1, 0, {0.0, 45.0 * d, 90.0 * d, -45.0 * d, 0.0});
}
void ShellElastic(benchmark::State& s) {
  runShell(s, materials::Elastic{materials::moduliFromYoung(210.0, 0.3)}, 1);
}
void ShellPlastic024Viscous(benchmark::State& s) {
  runShell(s, plastic024(), 1);
}
void ShellPlastic024Stiffness(benchmark::State& s) {
  runShell(s, plastic024(), 4);
}

// Args: threads, elements along x (400 x 250 = 100k; 40 x 250 = 10k, in cache), gather (1) or
// the kernel alone (0).
void shellArgs(benchmark::internal::Benchmark* b) {
  b->Args({1, 400, 1})
      ->Args({2, 400, 1})
      ->Args({1, 400, 0})
      ->Args({1, 40, 1})
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}
BENCHMARK(ShellPlastic024Viscous)->Apply(shellArgs);
BENCHMARK(ShellPlastic024Stiffness)->Apply(shellArgs);
BENCHMARK(ShellPlastic024Crash)->Apply(shellArgs);
BENCHMARK(ShellPlastic024CurveCrash)->Apply(shellArgs);
BENCHMARK(ShellPlastic024RateTableCrash)->Apply(shellArgs);
BENCHMARK(ShellPlastic024RateTableViscoplasticCrash)->Apply(shellArgs);
BENCHMARK(ShellComposite054)->Apply(shellArgs);
BENCHMARK(ShellElastic)->Apply(shellArgs);
// A fixed amount of work, for instruction counts under callgrind:
//   valgrind --tool=callgrind --toggle-collect='*shellBlockForces*' crumple_bench
//     --benchmark_filter=ShellCounted   -> Ir / (10 iterations x 10,000 elements)
void ShellCounted(benchmark::State& s) {
  ShellPlastic024Viscous(s);
}
BENCHMARK(ShellCounted)->Args({1, 40, 0})->Iterations(10)->Unit(benchmark::kMillisecond);

}  // namespace
