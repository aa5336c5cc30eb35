// Choices of a config held as enums: the file and every output spell them as text, the code
// past the parse compares enum values. One table per enum gives both.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace tbridge {

template <class E>
struct Named {
  E value;
  const char* name;
};

// The text of `value` in `table`; "" when the table lacks it (a subset table).
template <class E, std::size_t N>
constexpr const char* NameIn(const std::array<Named<E>, N>& table, E value) {
  for (const Named<E>& n : table) {
    if (n.value == value) return n.name;
  }
  return "";
}

// The value `text` names in `table`; nullopt when no entry spells it.
template <class E, std::size_t N>
constexpr std::optional<E> ValueIn(const std::array<Named<E>, N>& table, std::string_view text) {
  for (const Named<E>& n : table) {
    if (text == n.name) return n.value;
  }
  return std::nullopt;
}

// Every text of the table, in its order (an error lists them with core/json_reader.h's
// ChoiceText).
template <class E, std::size_t N>
std::vector<std::string> AllNames(const std::array<Named<E>, N>& table) {
  std::vector<std::string> names;
  for (const Named<E>& n : table) names.emplace_back(n.name);
  return names;
}

// The texts of `values` in `table`, in order.
template <class E, std::size_t N>
std::vector<std::string> NamesIn(const std::array<Named<E>, N>& table,
                                 const std::vector<E>& values) {
  std::vector<std::string> out;
  for (const E e : values) out.emplace_back(NameIn(table, e));
  return out;
}

// A choice key whose field is an enum: the visitor (core/config_visitors.h) sees the text, so
// the parse, the echo, Validate() and the README's table are those of a text choice among the
// table's names, and the parse writes the enum back. A visitor that writes a text outside the
// table (a test's) leaves a value outside it too, which Validate() refuses as it would the text.
template <class V, class F, std::size_t N>
void EnumChoice(V& v, const auto& key, F& field,
                const std::array<Named<std::remove_const_t<F>>, N>& table) {
  const std::vector<std::string> allowed = AllNames(table);
  std::string text = NameIn(table, field);
  if constexpr (std::is_const_v<F>) {
    v.Choice(key, static_cast<const std::string&>(text), allowed);
  } else {
    v.Choice(key, text, allowed);
    const auto it = std::find(allowed.begin(), allowed.end(), text);
    field = it != allowed.end() ? table[static_cast<std::size_t>(it - allowed.begin())].value
                                : static_cast<std::remove_const_t<F>>(-1);
  }
}

// EnumChoice for a list key whose field is a vector of enums (each one of the table's names,
// none twice: the visitor's Choices).
template <class V, class F, std::size_t N>
void EnumChoices(V& v, const auto& key, F& field,
                 const std::array<Named<typename std::remove_const_t<F>::value_type>, N>& table) {
  using E = typename std::remove_const_t<F>::value_type;
  const std::vector<std::string> allowed = AllNames(table);
  std::vector<std::string> texts = NamesIn(table, static_cast<const std::vector<E>&>(field));
  if constexpr (std::is_const_v<F>) {
    v.Choices(key, static_cast<const std::vector<std::string>&>(texts), allowed);
  } else {
    v.Choices(key, texts, allowed);
    field.clear();
    for (const std::string& t : texts)
      field.push_back(ValueIn(table, t).value_or(static_cast<E>(-1)));
  }
}

}  // namespace tbridge
