#pragma once
// Bézier ordinates of one segment of a degree-p B-spline from its local knots and de Boor
// ordinates, by blossoming: b_r = ψ[a^{p−r}, b^r] for the segment [a, b] = [u_{p−1}, u_p] of the
// local knots u_0..u_{2p−1}, the blossom evaluated by de Boor's recurrence
//   d_i^m = (1 − α) d_{i−1}^{m−1} + α d_i^{m−1},  α = (x_m − u_{i−1}) / (u_{i+p−m} − u_{i−1}),
// i = m..p, m = 1..p, with d_i^0 = c_i (i = 0..p). Templated on the scalar so that the knot
// dependence can be differentiated exactly with ceres::Jet (the Jacobian of section 4).
// Precondition (caller's): u non-decreasing with u_{p−1} < u_p (every denominator is positive).
namespace cagd::intrinsic::detail {

template <class T>
void bezier_from_de_boor(int p, const T* u, const T* c, T* b) {
    T d[5], x[4];  // p ≤ 4
    for (int r = 0; r <= p; ++r) {
        for (int m = 0; m < p; ++m) x[m] = m < p - r ? u[p - 1] : u[p];
        for (int i = 0; i <= p; ++i) d[i] = c[i];
        for (int m = 1; m <= p; ++m)
            for (int i = p; i >= m; --i) {
                const T alpha = (x[m - 1] - u[i - 1]) / (u[i + p - m] - u[i - 1]);
                d[i] = (T(1.0) - alpha) * d[i - 1] + alpha * d[i];
            }
        b[r] = d[p];
    }
}

}  // namespace cagd::intrinsic::detail
