// The units an input may carry (model/numerics/units.hpp): each declared factor against UDUNITS-2
// (the `udunits2` program, an independent definition of the same symbols), and the parser
// that reads "150um" and refuses what is not a unit of the dimension.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "model/numerics/units.hpp"

using namespace punchsweep::model;

namespace {

/// udunits2's factor F in "x/SI = F*(x/UNIT)", or a negative number when it is not there.
double udunits_factor(const std::string& unit, const std::string& si) {
  const std::string command = "udunits2 -H '" + unit + "' -W '" + si + "' 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return -1.0;
  std::array<char, 256> line{};
  while (std::fgets(line.data(), line.size(), pipe.get()) != nullptr) {
    const std::string text(line.data());
    const std::string head = "x/" + si + " = ";
    const auto at = text.find(head);
    if (at == std::string::npos) continue;
    const std::string rest = text.substr(at + head.size());
    if (rest.rfind("(x/", 0) == 0) return 1.0;  // "x/m = (x/m)": the unit itself
    return std::strtod(rest.c_str(), nullptr);
  }
  return -1.0;
}

}  // namespace

TEST(Units, every_declared_factor_is_udunits_own) {
  if (std::system("udunits2 -H m -W m > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "udunits2 (Debian's udunits-bin, installed by cmake/install-deps.sh) is not on PATH";
  }
  for (const Dimension d : {Dimension::length, Dimension::pressure, Dimension::time}) {
    const std::string si(units_of(d).front().name);
    EXPECT_EQ(units_of(d).front().si, 1.0) << si;
    for (const Unit& u : units_of(d)) {
      EXPECT_DOUBLE_EQ(udunits_factor(std::string(u.name), si), u.si) << u.name << " in " << si;
    }
  }
}

TEST(Units, a_number_and_a_unit_is_its_si_value_and_a_bare_number_is_none) {
  EXPECT_DOUBLE_EQ(parse_physical("150um", Dimension::length)->si(), 150e-6);
  EXPECT_DOUBLE_EQ(parse_physical(" 150 um ", Dimension::length)->si(), 150e-6);
  EXPECT_EQ(parse_physical("150\u00b5m", Dimension::length)->unit->name, "um");
  EXPECT_DOUBLE_EQ(parse_physical("2.5e-3mm", Dimension::length)->si(), 2.5e-6);
  EXPECT_DOUBLE_EQ(parse_physical("20kPa", Dimension::pressure)->si(), 2e4);
  EXPECT_DOUBLE_EQ(parse_physical("1.5 h", Dimension::time)->si(), 5400.0);
  // Between declared units the ratio is an integer or its reciprocal, applied exactly:
  // 1e-3 / 1e-6 in floating point is 999.9999999999999.
  const Unit& mm = *find_unit(Dimension::length, "mm");
  const Unit& um = *find_unit(Dimension::length, "um");
  EXPECT_EQ(convert(0.15, mm, um), 150.0);
  EXPECT_EQ(convert(150.0, um, mm), 0.15);
  EXPECT_EQ(convert(2.0, *find_unit(Dimension::time, "h"), *find_unit(Dimension::time, "min")), 120.0);
  EXPECT_FALSE(parse_physical("0.75", Dimension::length).has_value());
  EXPECT_FALSE(parse_physical("1e-3", Dimension::pressure).has_value());
  EXPECT_EQ(unit_names(Dimension::pressure), "Pa, kPa, MPa or GPa");
  EXPECT_EQ(unit_names(Dimension::time), "s, ms, min or h");
}

TEST(Units, a_unit_of_another_dimension_or_no_number_is_refused_with_the_valid_units) {
  for (const auto& [text, d, words] : {std::tuple{"150kPa", Dimension::length, "'kPa' is a pressure, not a length; valid: m, mm, um or nm"},
                                       std::tuple{"20 psi", Dimension::pressure, "'psi' is not a pressure unit; valid: Pa, kPa, MPa or GPa"},
                                       std::tuple{"2 min", Dimension::length, "'min' is a time, not a length"},
                                       std::tuple{"um", Dimension::length, "is not a number, or a number and a length unit"},
                                       std::tuple{"", Dimension::time, "is not a number, or a number and a time unit (s, ms, min or h)"}}) {
    try {
      parse_physical(text, d);
      ADD_FAILURE() << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
}
