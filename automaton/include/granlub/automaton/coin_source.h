// The rule stream's coins. Philox keeps a reservoir of coin bits; during a step the engine holds
// that reservoir in a local (a register) and hands it back afterwards, so a source that has one is
// driven through coin_from(). The scripted test source has none and is asked coin() directly.
// Same words, same bits, same order either way.
#pragma once
#include <concepts>

namespace granlub::automaton {

template <class R>
concept CoinReservoir = requires(R r, typename R::Coins& k) {
    { r.coin_from(k) } -> std::same_as<bool>;
    { r.coins() } -> std::same_as<typename R::Coins&>;
};

// The reservoir type of R, or an empty placeholder when R has none.
template <class R, bool = CoinReservoir<R>>
struct CoinStateOf { struct type {}; };
template <class R>
struct CoinStateOf<R, true> { using type = typename R::Coins; };

template <class R>
using CoinState = typename CoinStateOf<R>::type;

// Load the reservoir out of the source at the start of a step, store it back at the end.
template <class R>
CoinState<R> take_coins(R& rng) {
    if constexpr (CoinReservoir<R>) return rng.coins(); else return {};
}
template <class R>
void give_back_coins(R& rng, const CoinState<R>& coins) {
    if constexpr (CoinReservoir<R>) rng.coins() = coins;
}

// One fair coin from `rng`, drawn from the held reservoir when the source has one.
template <class R>
bool draw_coin(R& rng, CoinState<R>& coins) {
    if constexpr (CoinReservoir<R>) return rng.coin_from(coins); else return rng.coin();
}

}  // namespace granlub::automaton
