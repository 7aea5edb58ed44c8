// Block-tridiagonal LU with 2x2 blocks (block Thomas algorithm), for the interleaved (u, s)
// Newton systems of the FV solver (docs/continuum-model.md §6.1: bandwidth 3 in blocks). O(N), no allocation after
// construction; two right-hand sides at once for the bordered Fill-mode system.
#pragma once
#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace granlub::continuum::detail {

class BlockTridiagonal {
public:
    using Block = Eigen::Matrix2d;
    using Vec = Eigen::Vector2d;

    explicit BlockTridiagonal(std::size_t n) : lower(n), diag(n), upper(n), inv_(n) {}
    std::size_t size() const { return diag.size(); }

    // Factorises in place; false when a pivot block is singular.
    bool factorise() {
        const std::size_t n = diag.size();
        inv_[0] = diag[0];
        for (std::size_t i = 0; i < n; ++i) {
            if (i > 0) {
                // L_i = lower_i * inv(D'_{i-1});  D'_i = diag_i - L_i upper_{i-1}
                lower[i] = lower[i] * inv_[i - 1];
                inv_[i] = diag[i] - lower[i] * upper[i - 1];
            }
            const double det = inv_[i].determinant();
            const double scale = inv_[i].cwiseAbs().maxCoeff();
            if (!(std::abs(det) > 1e-300) || !(std::abs(det) > 1e-14 * scale * scale)) return false;
            inv_[i] = inv_[i].inverse().eval();
        }
        return true;
    }

    // Solves in place for a factorised matrix.
    void solve(std::vector<Vec>& x) const {
        const std::size_t n = diag.size();
        for (std::size_t i = 1; i < n; ++i) x[i] -= lower[i] * x[i - 1];
        x[n - 1] = inv_[n - 1] * x[n - 1];
        for (std::size_t i = n - 1; i-- > 0;) x[i] = inv_[i] * (x[i] - upper[i] * x[i + 1]);
    }

    std::vector<Block> lower, diag, upper;  // row i: lower (cols of i-1), diag, upper (cols of i+1)

private:
    std::vector<Block> inv_;
};

}  // namespace granlub::continuum::detail
