// The work of a force over one step, kept as its two halves.
//
// Energies are reported with the kinetic energy central differences conserve,
// 1/2 m v(n-1/2) . v(n+1/2), and the internal energy at x(n). For a linear system that sum
// changes over [t(n-1), t(n)] by exactly (f(n-1) + f(n)) / 2 . v(n-1/2) dt of the external
// force f (docs/theory.md, "Energy balance"). The work of the step dt(n) centred on t(n),
// f(n) . (v(n-1/2) + v(n+1/2)) / 2 dt(n), is known once v(n+1/2) is: its half at v(n-1/2)
// belongs to the balance at t(n), its half at v(n+1/2) to the next one. Counting both at t(n)
// makes the ratio dip by that half whenever a force grows fast (a punch striking a sheet:
// 6 % at contact) and come back when it falls.
#pragma once

namespace crumple::constraints {

struct StepWork {
  double behind = 0.0;  // f(n) . v(n-1/2) dt(n) / 2
  double ahead = 0.0;   // f(n) . v(n+1/2) dt(n) / 2
  double total() const { return behind + ahead; }
  StepWork& operator+=(const StepWork& o) {
    behind += o.behind;
    ahead += o.ahead;
    return *this;
  }
};

// The two halves of an impulse's work: p = f(n) dt(n) (a force times the step, or the
// momentum change m dv a constraint imposes) with the velocities before and after.
inline StepWork impulseWork(double p, double v_before, double v_after) {
  return {0.5 * p * v_before, 0.5 * p * v_after};
}

}  // namespace crumple::constraints
