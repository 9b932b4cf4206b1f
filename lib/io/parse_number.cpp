#include "io/parse_number.hpp"

#include "core/errors.hpp"
#include "io/line_reader.hpp"

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <string>
#include <system_error>

namespace cmp::io {

namespace {
// from_chars rejects a leading '+', which other programs write ("%+e"); accept it before a
// digit or a point only, so "+-1" and "+nan" stay errors.
std::string_view drop_plus(std::string_view token) {
  if (token.size() >= 2 && token[0] == '+' &&
      (std::isdigit(static_cast<unsigned char>(token[1])) || token[1] == '.'))
    return token.substr(1);
  return token;
}

enum class Outcome { ok, not_a_number, not_finite, out_of_range };

template <class Real>
Outcome parse_real(std::string_view token, Real& out) {
  token = drop_plus(token);
  Real value{};
  const auto [end, ec] =
      std::from_chars(token.data(), token.data() + token.size(), value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return Outcome::out_of_range;
  if (ec != std::errc() || end != token.data() + token.size() || token.empty())
    return Outcome::not_a_number;
  if (!std::isfinite(value)) return Outcome::not_finite;
  out = value;
  return Outcome::ok;
}

template <class Real>
Real parse_real_or_throw(std::string_view token, const std::string& file, long line,
                         std::string_view what) {
  Real value{};
  switch (parse_real(token, value)) {
    case Outcome::ok:
      return value;
    case Outcome::not_finite:
      throw InputError(file, line,
                       "expected " + std::string(what) + " (finite), got " + quote_token(token));
    case Outcome::out_of_range:
      throw InputError(file, line,
                       "expected " + std::string(what) + " (in floating-point range), got " +
                           quote_token(token));
    default:
      throw InputError(file, line, "expected " + std::string(what) + ", got " + quote_token(token));
  }
}
}  // namespace

bool try_parse_double(std::string_view token, double& out) {
  return parse_real(token, out) == Outcome::ok;
}

bool try_parse_float(std::string_view token, float& out) {
  return parse_real(token, out) == Outcome::ok;
}

bool try_parse_integer(std::string_view token, long long& out) {
  token = drop_plus(token);
  long long value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size() || token.empty()) return false;
  out = value;
  return true;
}

double parse_double(std::string_view token, const std::string& file, long line,
                    std::string_view what) {
  return parse_real_or_throw<double>(token, file, line, what);
}

float parse_float(std::string_view token, const std::string& file, long line,
                  std::string_view what) {
  return parse_real_or_throw<float>(token, file, line, what);
}

long long parse_integer(std::string_view token, const std::string& file, long line,
                        std::string_view what, long long lo, long long hi) {
  long long value = 0;
  if (!try_parse_integer(token, value)) {
    // Tell an integer that does not fit from a token that is no integer at all.
    const auto digits =
        token.substr(!token.empty() && (token[0] == '-' || token[0] == '+') ? 1 : 0);
    const bool all_digits =
        !digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos;
    throw InputError(file, line,
                     "expected " + std::string(what) + ", got " + quote_token(token) +
                         (all_digits ? " (out of range)" : ""));
  }
  if (value < lo || value > hi)
    throw InputError(file, line,
                     "expected " + std::string(what) + " in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "], got " + quote_token(token));
  return value;
}

int parse_int(std::string_view token, const std::string& file, long line, std::string_view what) {
  return static_cast<int>(parse_integer(token, file, line, what, INT_MIN, INT_MAX));
}

}  // namespace cmp::io
