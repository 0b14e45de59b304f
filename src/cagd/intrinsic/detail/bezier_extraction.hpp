#pragma once
// Bézier ordinates of one segment of a degree-p B-spline from its local knots and de Boor
// ordinates, by blossoming: b_r = ψ[a^{p−r}, b^r] for the segment [a, b] = [u_{p−1}, u_p] of the
// local knots u_0..u_{2p−1}, the blossom evaluated by de Boor's recurrence
//   d_i^m = (1 − α) d_{i−1}^{m−1} + α d_i^{m−1},  α = (x_m − u_{i−1}) / (u_{i+p−m} − u_{i−1}),
// i = m..p, m = 1..p, with d_i^0 = c_i (i = 0..p). Templated on the scalar so that the knot
// dependence can be differentiated exactly with ceres::Jet (the Jacobian of section 4).
// Precondition (caller's): u non-decreasing with u_{p−1} < u_p (every denominator is positive).
#include <stdexcept>

namespace cagd::intrinsic::detail {

// The degree as a template argument: the work arrays hold exactly what the recurrence uses (for
// ceres::Jet, whose constructor zeroes every slot, the unused ones cost as much as the used).
template <int P, class T>
void bezier_from_de_boor_of_degree(const T* u, const T* c, T* b) {
    T d[P + 1], x[P];
    for (int r = 0; r <= P; ++r) {
        for (int m = 0; m < P; ++m) x[m] = m < P - r ? u[P - 1] : u[P];
        for (int i = 0; i <= P; ++i) d[i] = c[i];
        for (int m = 1; m <= P; ++m)
            for (int i = P; i >= m; --i) {
                const T alpha = (x[m - 1] - u[i - 1]) / (u[i + P - m] - u[i - 1]);
                d[i] = (T(1.0) - alpha) * d[i - 1] + alpha * d[i];
            }
        b[r] = d[P];
    }
}

// The same for a degree p known at run time, 2 ≤ p ≤ 4 (KnotLayout's degrees; another is a logic error).
template <class T>
void bezier_from_de_boor(int p, const T* u, const T* c, T* b) {
    switch (p) {
        case 2: bezier_from_de_boor_of_degree<2>(u, c, b); break;
        case 3: bezier_from_de_boor_of_degree<3>(u, c, b); break;
        case 4: bezier_from_de_boor_of_degree<4>(u, c, b); break;
        default: throw std::logic_error("cagd::intrinsic::detail::bezier_from_de_boor: degree outside 2..4");
    }
}

}  // namespace cagd::intrinsic::detail
