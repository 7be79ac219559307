// Principal values and axes of a symmetric 3 x 3 tensor in Voigt order (xx, yy, zz, xy, yz,
// zx; tensor shear components), for laws that act on principal stresses (*MAT_CRUSHABLE_FOAM).
//
// Cyclic Jacobi rotations (Golub and Van Loan, Matrix Computations, 4th ed., 2013, sec. 8.5:
// the 2 x 2 symmetric Schur decomposition and the cyclic-by-row Jacobi method): each rotation
// zeroes one off-diagonal entry; a sweep visits (xy, xz, yz) in that fixed order and converges
// quadratically. Chosen over
// the closed-form cubic because it stays accurate for repeated and nearly repeated principal
// values, where the eigenvectors of the cubic's roots are ill-conditioned, and because it is a
// pure function of its six inputs (no branch on anything else), so a point's result does not
// depend on where it sits in a batch, a rank or a thread.
#pragma once

#include <array>

namespace crumple::materials {

using Voigt = std::array<double, 6>;

struct Principal {
  std::array<double, 3> value{};                // ascending
  std::array<std::array<double, 3>, 3> axis{};  // axis[k]: unit vector of value[k] (x, y, z)
};

// The principal values (ascending) and orthonormal axes of t.
Principal principalOf(const Voigt& t);

// The tensor sum_k value[k] axis[k] (x) axis[k], in Voigt order.
Voigt fromPrincipal(const std::array<double, 3>& value,
                    const std::array<std::array<double, 3>, 3>& axis);

// t with each principal value confined to [lo, hi] (lo <= hi), on the same principal axes; t
// itself, bit for bit, when all three already lie there (no rounding from the decomposition).
Voigt clampPrincipal(const Voigt& t, double lo, double hi);

}  // namespace crumple::materials
