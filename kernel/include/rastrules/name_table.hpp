// SPDX-License-Identifier: MIT
// One table of strings per enumeration: Names<E>::table pairs every enumerator of E with its one
// spelling, declared next to E, and name_of, from_name and to_string read it, so that no two
// places can spell a value differently. Two kinds of spelling use it: the words a scene, the
// command line or a report parses back (rastrules/names.hpp gathers those of the scene's
// conventions; from_name parses them), and display text that is only printed, such as a
// triangle's status "culled (back-facing)" or a generator's tie class (never parsed).

#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace rastrules {

// Names<E>::table: every enumerator of E with its spelling, in the order error messages list
// them. Specialised next to each enumeration.
template <class E> struct Names;

template <std::size_t N, class E> using NameTable = std::array<std::pair<std::string_view, E>, N>;

// The table of an enumeration whose enumerators are 0, 1, ..., N - 1 in the order they are
// declared: words[i] spells E(i).
template <class E, std::size_t N>
[[nodiscard]] consteval NameTable<N, E> in_enum_order(const std::string_view (&words)[N]) {
  NameTable<N, E> table{};
  for (std::size_t i = 0; i < N; ++i)
    table[i] = {words[i], static_cast<E>(i)};
  return table;
}

// Returns the spelling of e (`otherwise` for a value outside the table).
template <class E>
[[nodiscard]] constexpr std::string_view name_of(E e, std::string_view otherwise = "unknown") {
  for (const auto& [name, value] : Names<E>::table)
    if (value == e)
      return name;
  return otherwise;
}

// Returns the enumerator spelled `word`, or nothing.
template <class E> [[nodiscard]] constexpr std::optional<E> from_name(std::string_view word) {
  for (const auto& [name, value] : Names<E>::table)
    if (name == word)
      return value;
  return std::nullopt;
}

// to_string(e) of every enumeration with a table: its spelling. Namespaces nested in rastrules
// that declare such enumerations bring it in (`using rastrules::to_string;`) so that
// ns::to_string(e) and argument-dependent calls find it.
template <class E>
requires requires {
  Names<E>::table;
}
[[nodiscard]] constexpr std::string_view to_string(E e) {
  return name_of(e);
}

} // namespace rastrules
