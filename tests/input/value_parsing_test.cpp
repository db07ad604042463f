// The whole-text readers of input/value_parsing.hpp: what they take, and that what they
// refuse is a UsageError naming the option and its range.
#include "input/value_parsing.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "input/usage_error.hpp"

namespace punchsweep::input {
namespace {

std::string seed_refusal(const std::string& text) {
  try {
    const std::uint64_t seed = parse_seed(text, "--seed");
    return "accepted as " + std::to_string(seed);
  } catch (const UsageError& e) {
    return e.what();
  }
}

TEST(ValueParsing, a_seed_is_any_whole_number_a_64_bit_generator_takes) {
  EXPECT_EQ(parse_seed("0", "--seed"), 0u);
  EXPECT_EQ(parse_seed("1", "--seed"), 1u);
  EXPECT_EQ(parse_seed("18446744073709551615", "--seed"), std::numeric_limits<std::uint64_t>::max());
}

TEST(ValueParsing, a_negative_fractional_or_too_large_seed_is_refused_with_its_range) {
  // "-1" would wrap round to 2^64 - 1 as an unsigned conversion reads it.
  for (const std::string text : {"-1", "1.5", "1e3", "+1", "", " 1", "18446744073709551616", "99999999999999999999999", "one"}) {
    EXPECT_EQ(seed_refusal(text), "--seed = '" + text + "' is outside its range: an integer in [0, 2^64-1 = 18446744073709551615]")
        << text;
  }
}

}  // namespace
}  // namespace punchsweep::input
