// A scripted random source for the rule tests (docs/automaton-model.md §7.1): every draw the engine makes
// must have been scripted, in order, so a test fixes the exact outcome of every rule and also
// proves which draws a rule makes.
#pragma once
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>

struct ScriptedRng {
    std::deque<std::uint32_t> ints;
    std::deque<bool> coins;
    std::deque<double> uniforms;

    std::uint32_t below(std::uint32_t n) {
        if (ints.empty()) throw std::logic_error("unscripted below(" + std::to_string(n) + ")");
        const std::uint32_t v = ints.front();
        ints.pop_front();
        if (v >= n) throw std::logic_error("scripted below() value out of range");
        return v;
    }
    bool coin() {
        if (coins.empty()) throw std::logic_error("unscripted coin()");
        const bool b = coins.front();
        coins.pop_front();
        return b;
    }
    double uniform() {
        if (uniforms.empty()) throw std::logic_error("unscripted uniform()");
        const double u = uniforms.front();
        uniforms.pop_front();
        return u;
    }
    bool exhausted() const { return ints.empty() && coins.empty() && uniforms.empty(); }
};
