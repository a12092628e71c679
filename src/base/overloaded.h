#pragma once
// The usual visitor helper for std::visit over the command variant: one lambda per alternative.

namespace gloss {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace gloss
