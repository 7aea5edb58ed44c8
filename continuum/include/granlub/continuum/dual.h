// Forward-mode dual numbers with N derivative directions. The closures are templated on the
// scalar type, so evaluating them with Dual<1> in nu gives exact d/dnu, and the finite-volume
// stencil evaluated with Dual<7> gives exact Jacobian rows (docs/continuum-model.md §2.4: exact derivatives, never
// nested numerical differentiation).
#pragma once
#include <array>
#include <cmath>

namespace granlub::continuum {

template <int N>
struct Dual {
    double v = 0;
    std::array<double, N> d{};

    Dual() = default;
    Dual(double value) : v(value) {}  // NOLINT: constants lift implicitly
    static Dual variable(double value, int k, double seed = 1.0) {
        Dual x(value);
        x.d[static_cast<std::size_t>(k)] = seed;
        return x;
    }
    // A value with a known derivative dv in direction k (chain-rule lifting).
    static Dual lifted(double value, int k, double dv) { return variable(value, k, dv); }

    Dual& operator+=(const Dual& o) {
        v += o.v;
        for (int k = 0; k < N; ++k) d[k] += o.d[k];
        return *this;
    }
    Dual& operator-=(const Dual& o) {
        v -= o.v;
        for (int k = 0; k < N; ++k) d[k] -= o.d[k];
        return *this;
    }
    Dual& operator*=(const Dual& o) {
        for (int k = 0; k < N; ++k) d[k] = d[k] * o.v + v * o.d[k];
        v *= o.v;
        return *this;
    }
    Dual& operator/=(const Dual& o) {
        const double inv = 1.0 / o.v;
        const double q = v * inv;
        for (int k = 0; k < N; ++k) d[k] = (d[k] - q * o.d[k]) * inv;
        v = q;
        return *this;
    }
};

template <int N> Dual<N> operator+(Dual<N> a, const Dual<N>& b) { return a += b; }
template <int N> Dual<N> operator-(Dual<N> a, const Dual<N>& b) { return a -= b; }
template <int N> Dual<N> operator*(Dual<N> a, const Dual<N>& b) { return a *= b; }
template <int N> Dual<N> operator/(Dual<N> a, const Dual<N>& b) { return a /= b; }
template <int N> Dual<N> operator+(Dual<N> a, double b) { a.v += b; return a; }
template <int N> Dual<N> operator+(double b, Dual<N> a) { a.v += b; return a; }
template <int N> Dual<N> operator-(Dual<N> a, double b) { a.v -= b; return a; }
template <int N> Dual<N> operator-(double b, const Dual<N>& a) {
    Dual<N> r(b - a.v);
    for (int k = 0; k < N; ++k) r.d[k] = -a.d[k];
    return r;
}
template <int N> Dual<N> operator-(const Dual<N>& a) { return 0.0 - a; }
template <int N> Dual<N> operator*(Dual<N> a, double b) {
    a.v *= b;
    for (auto& x : a.d) x *= b;
    return a;
}
template <int N> Dual<N> operator*(double b, Dual<N> a) { return a * b; }
template <int N> Dual<N> operator/(Dual<N> a, double b) { return a * (1.0 / b); }
template <int N> Dual<N> operator/(double b, const Dual<N>& a) { return Dual<N>(b) / a; }

// f(a) with f(a.v) = fv and f'(a.v) = fd.
template <int N> Dual<N> chain(const Dual<N>& a, double fv, double fd) {
    Dual<N> r(fv);
    for (int k = 0; k < N; ++k) r.d[k] = fd * a.d[k];
    return r;
}
// The same for a double, for code templated on the scalar: f(a).
inline double chain(double /*a*/, double fv, double /*fd*/) { return fv; }
template <int N> Dual<N> sqrt(const Dual<N>& a) { const double s = std::sqrt(a.v); return chain(a, s, 0.5 / s); }
template <int N> Dual<N> cbrt(const Dual<N>& a) {
    const double c = std::cbrt(a.v);
    return chain(a, c, c / (3.0 * a.v));
}
template <int N> Dual<N> exp(const Dual<N>& a) { const double e = std::exp(a.v); return chain(a, e, e); }
template <int N> Dual<N> log(const Dual<N>& a) { return chain(a, std::log(a.v), 1.0 / a.v); }
template <int N> Dual<N> pow(const Dual<N>& a, double p) {
    const double r = std::pow(a.v, p);
    return chain(a, r, p * r / a.v);
}
template <int N> Dual<N> abs(const Dual<N>& a) { return a.v < 0 ? -a : a; }

// Value of a double or a dual, for code templated on the scalar.
inline double value(double x) { return x; }
template <int N> double value(const Dual<N>& x) { return x.v; }

using D1 = Dual<1>;  // value and d/dnu

}  // namespace granlub::continuum
