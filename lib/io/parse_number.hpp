#pragma once
// Strict conversion of one token to a number: the whole token must be the number (no trailing
// junk, no surrounding spaces), finite (no NaN, no Inf) and in range. The throwing forms give
// cmp::InputError(file, line, "expected <what>, got 'abc'") for the readers of lib/io.
#include <climits>
#include <string>
#include <string_view>

namespace cmp::io {

// The largest magnitude of a coordinate, box side or radius the readers of geometry take (OFF,
// extended XYZ sphere packings): cubes of differences of such numbers (volumes) stay finite.
inline constexpr double kMaxCoordinate = 1e100;

// True and out set when token is a whole finite double ("1", "-0.5", "+1e-8", ".5").
// NaN, Inf, hexadecimal, overflow and underflow to zero (e.g. "1e-400") give false.
bool try_parse_double(std::string_view token, double& out);
// Same for float (parsed directly, so a float written in shortest form reads back exactly).
bool try_parse_float(std::string_view token, float& out);
// True and out set when token is a whole decimal integer that fits in a long long.
bool try_parse_integer(std::string_view token, long long& out);

// The token as a finite double; throws cmp::InputError(file, line, "expected <what>, got
// '<token>'") otherwise, with "<what> (finite)" for NaN/Inf and "<what> (in floating-point
// range)" for overflow. what names the value for the reader, e.g. "a coordinate".
double parse_double(std::string_view token, const std::string& file, long line,
                    std::string_view what = "a number");
float parse_float(std::string_view token, const std::string& file, long line,
                  std::string_view what = "a number");
// The token as an integer within [lo, hi]; throws cmp::InputError otherwise ("expected <what>,
// got '1.5'", "expected <what> in [lo, hi], got '-3'").
long long parse_integer(std::string_view token, const std::string& file, long line,
                        std::string_view what = "an integer", long long lo = LLONG_MIN,
                        long long hi = LLONG_MAX);
// parse_integer limited to the range of int.
int parse_int(std::string_view token, const std::string& file, long line,
              std::string_view what = "an integer");

}  // namespace cmp::io
