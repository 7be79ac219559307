// Hex kernel throughput: one element pass (strain rate, material, stress divergence,
// hourglass, time step) plus the ordered nodal gather, on a 100k-element brick; the same brick
// of thick shells (*SECTION_TSHELL ELFORM 1 and 2, 5 points through the thickness: TShell*).
// Reports ns per element-cycle; run with OMP_NUM_THREADS=1 and =2 for the speed-up.
//   build/release/bench/crumple_bench --benchmark_filter=Hex8
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <functional>

#include "brick_model.hpp"
#include "domain/subdomain.hpp"
#include "elements/hex8.hpp"
#include "elements/tshell.hpp"
#include "model/model.hpp"

namespace {

using namespace crumple;

// tshell_nip > 0: the elements are thick shells with that many points through the thickness,
// of formulation tshell_form (model::kThickShellOnePoint or kThickShellSelective).
model::Model brick(int nx, int ny, int nz, model::MaterialLaw law, int ihq, int tshell_nip,
                   int tshell_form) {
  testing::BrickOptions opt;
  opt.law = law;
  opt.ihq = ihq;
  opt.qh = 0.05;
  // A mild distortion so no shortcut of a perfect grid applies.
  opt.position = [](int i, int j, int k) {
    return model::Vec3{i + 0.05 * std::sin(j + k), j + 0.05 * std::cos(i + k), double(k)};
  };
  auto m = testing::brickModel(nx, ny, nz, opt);
  if (tshell_nip > 0) {
    m.solid_sections[0].elform = tshell_form;
    m.solid_sections[0].nip = tshell_nip;
  }
  return m;
}

// `complete` adds what the law needs beyond its parameters (an equation of state, a curve).
void runKernel(benchmark::State& state, model::MaterialLaw law, int ihq, int tshell_nip = 0,
               int tshell_form = model::kThickShellOnePoint,
               const std::function<void(model::Model&)>& complete = {}) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  // Range 1: brick edge in elements along z (40 = 100k elements; 4 = 10k, which fits in cache).
  auto m = brick(50, 50, static_cast<int>(state.range(1)), law, ihq, tshell_nip, tshell_form);
  if (complete) complete(m);
  auto sd = domain::buildSerialSubdomain(m);
  std::vector<double> dt_e;
  for (auto& b : sd.solid_blocks) elements::initializeSolids(b, sd.x0, sd.slots.data(), dt_e, {});
  // A compressive, shearing velocity field large enough to yield the plastic material.
  for (std::size_t n = 0; n < sd.numNodes(); ++n) {
    const double* x = &sd.x0[3 * n];
    sd.v[3 * n] = 2.0 * x[1] - 1.0 * x[0];
    sd.v[3 * n + 1] = 0.5 * x[2];
    sd.v[3 * n + 2] = -3.0 * x[2];
  }
  const double dt = 1e-5;
  elements::BulkViscosity bv;
  const std::size_t nn = sd.numNodes();
  for (auto _ : state) {
    for (auto& b : sd.solid_blocks)
      if (b.thickShell())
        elements::computeThickShellForces(b, sd.x, sd.v, dt, sd.slots.data(), 0, b.size());
      else
        elements::computeSolidForces(b, sd.x, sd.v, dt, bv, sd.slots.data());
#pragma omp parallel for schedule(static)
    for (std::size_t n = 0; n < nn; ++n) {
      double s[3] = {0, 0, 0};
      for (int32_t k = sd.internal.ptr[n]; k < sd.internal.ptr[n + 1]; ++k)
        for (int c = 0; c < 3; ++c)
          s[c] += sd.slots[3 * std::size_t(sd.internal.slot[std::size_t(k)]) + c];
      for (int c = 0; c < 3; ++c) sd.f[3 * n + c] = s[c];
    }
    benchmark::DoNotOptimize(sd.f.data());
  }
  const double elems = double(m.solids.size());
  state.counters["ns_per_element_cycle"] =
      benchmark::Counter(elems * double(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["elements"] = elems;
}

void Hex8Elastic(benchmark::State& s) {
  runKernel(s, materials::Elastic::Params{210.0, 0.3}, 4);
}
void Hex8PlasticHourglassStiffness(benchmark::State& s) {
  materials::PiecewiseLinear::Params law;
  law.E = 210.0;
  law.nu = 0.3;
  law.sigy = 0.001;  // yields at once under the imposed strain rate
  law.etan = 1.0;
  runKernel(s, law, 4);
}
void Hex8PlasticKinematicViscousHourglass(benchmark::State& s) {
  materials::PlasticKinematic::Params law;
  law.E = 210.0;
  law.nu = 0.3;
  law.sigy = 0.001;
  law.etan = 1.0;
  law.beta = 0.5;
  runKernel(s, law, 2);
}

// Args: threads, layers of 50 x 50 elements (40 layers = 100k elements; 4 = 10k, which fits in
// the caches and shows the kernel's arithmetic cost apart from memory traffic).
void hexArgs(benchmark::internal::Benchmark* b) {
  b->Args({1, 40})->Args({2, 40})->Args({1, 4})->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK(Hex8Elastic)->Apply(hexArgs);
// A fixed amount of work, for instruction counts under callgrind (wall time on a shared machine
// varies by tens of percent; instruction counts do not):
//   valgrind --tool=callgrind --toggle-collect='*solidBlockForces*' crumple_bench
//     --benchmark_filter=Hex8Counted   -> Ir / (10 iterations x 10,000 elements)
void Hex8Counted(benchmark::State& s) {
  Hex8PlasticKinematicViscousHourglass(s);
}
BENCHMARK(Hex8Counted)->Args({1, 4})->Iterations(10)->Unit(benchmark::kMillisecond);
BENCHMARK(Hex8PlasticHourglassStiffness)->Apply(hexArgs);
void TShellElastic(benchmark::State& s) {
  runKernel(s, materials::Elastic::Params{210.0, 0.3}, 4, 5);
}
// A soft plastic law that the benchmark's velocity field yields.
materials::PiecewiseLinear::Params softPlastic() {
  materials::PiecewiseLinear::Params law;
  law.E = 210.0;
  law.nu = 0.3;
  law.sigy = 0.001;
  law.etan = 1.0;
  return law;
}
void TShellPlasticHourglassStiffness(benchmark::State& s) {
  runKernel(s, softPlastic(), 4, 5);
}
BENCHMARK(TShellElastic)->Apply(hexArgs);
BENCHMARK(TShellPlasticHourglassStiffness)->Apply(hexArgs);
// ELFORM 2: 2 x 2 points in the plane, no hourglass control (the IHQ is not used).
void TShell2Plastic(benchmark::State& s) {
  runKernel(s, softPlastic(), 4, 5, model::kThickShellSelective);
}
BENCHMARK(TShell2Plastic)->Apply(hexArgs);
// Instruction counts as Hex8Counted:
//   valgrind --tool=callgrind --toggle-collect='*thickShellBlockForces*' crumple_bench
//     --benchmark_filter=TShellCounted   -> Ir / (10 iterations x 10,000 elements)
void TShellCounted(benchmark::State& s) {
  TShellPlasticHourglassStiffness(s);
}
BENCHMARK(TShellCounted)->Args({1, 4})->Iterations(10)->Unit(benchmark::kMillisecond);
BENCHMARK(Hex8PlasticKinematicViscousHourglass)->Apply(hexArgs);

// Crash and impact laws of issue 13 on the same brick, each yielding (or crushing) at once
// under the imposed velocity field: *MAT_JOHNSON_COOK with an *EOS_LINEAR_POLYNOMIAL (the law
// takes its pressure from the part's equation of state), with damage D1-D5 and adiabatic
// heating (OFHC copper's constants, Johnson & Cook 1985, but A small so that every point is
// plastic from the first pass); *MAT_SOIL_AND_FOAM with a pressure curve and a Drucker-Prager
// like surface (a0 + a1 p + a2 p^2).
void Hex8JohnsonCook(benchmark::State& s) {
  materials::JohnsonCook::Params jc;
  jc.rho = 8.96e-6;
  jc.G = 46.0;
  jc.a = 0.001;
  jc.b = 0.292;
  jc.n = 0.31;
  jc.c = 0.025;
  jc.m = 1.09;
  jc.tm = 1356.0;
  jc.tr = 293.0;
  jc.epso = 1.0;
  jc.cp = 383.0;
  jc.pc = -10.0;
  jc.d = {0.54, 4.89, -3.03, 0.014, 1.12};
  runKernel(s, jc, 4, 0, model::kThickShellOnePoint, [](model::Model& m) {
    model::EquationOfState eos;
    eos.id = 1;
    eos.eos.form = materials::Eos::Form::LinearPolynomial;
    eos.eos.c = {0.0, 140.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // C1 = K, GPa
    m.eos.push_back(eos);
    m.parts[0].eos = 0;
  });
}
void Hex8SoilFoam(benchmark::State& s) {
  materials::SoilAndFoam::Params soil;
  soil.G = 0.05;
  soil.kun = 0.5;
  soil.a0 = 1e-6;
  soil.a1 = 1e-3;
  soil.a2 = 0.3;
  soil.pc = -1e-4;
  soil.curve = 0;
  runKernel(s, soil, 4, 0, model::kThickShellOnePoint, [](model::Model& m) {
    model::Curve c;
    c.id = 1;
    c.x = {0.0, -0.05, -0.1, -0.3};  // ln(V / V0), as a deck's LCID
    c.y = {0.0, 0.01, 0.03, 0.2};    // pressure, GPa
    m.curves.push_back(c);
  });
}
BENCHMARK(Hex8JohnsonCook)->Apply(hexArgs);
BENCHMARK(Hex8SoilFoam)->Apply(hexArgs);

}  // namespace
