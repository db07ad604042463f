// The one rule for an input number (input/scaled_value.hpp): a bare number is in its scale,
// a number with a unit is divided by the scale. Expected values are exact quotients worked
// out here (150 um / 50 um = 3), not the code's.
#include "input/scaled_value.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace punchsweep::input {
namespace {

model::Physical physical(double number, model::Dimension dimension, const char* unit) {
  return {number, model::find_unit(dimension, unit)};
}

PhysicalScales silicone() {
  PhysicalScales scales;
  scales.R = physical(50.0, model::Dimension::length, "um");
  scales.E0_star = physical(4.0e6, model::Dimension::pressure, "Pa");
  scales.time = physical(1.0, model::Dimension::time, "s");
  return scales;
}

std::string message(const std::string& text, const Scale& scale) {
  try {
    read_scaled(text, scale);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ScaledValue, ABareNumberIsInItsScaleAndAUnitIsDividedByIt) {
  const Scale length = *scale_of("R", silicone());
  EXPECT_EQ(read_scaled("0.75", length), 0.75);
  EXPECT_EQ(read_scaled("150um", length), 3.0);
  EXPECT_EQ(read_scaled("150 um", length), 3.0);
  EXPECT_EQ(read_scaled("0.15mm", length), 3.0);  // converted as integers: exact
  EXPECT_EQ(read_scaled("150000nm", length), 3.0);
  EXPECT_EQ(read_scaled("2um", length), 2.0 / 50.0);
  const Scale pressure = *scale_of("E0/(1-nu^2)", silicone());
  EXPECT_EQ(read_scaled("2kPa", pressure), 2000.0 / 4.0e6);
  EXPECT_EQ(read_scaled("0.002MPa", pressure), 2000.0 / 4.0e6);
  const Scale time = *scale_of("T_eps", silicone());
  EXPECT_EQ(read_scaled("2min", time), 120.0);
  EXPECT_EQ(read_scaled("1h", time), 3600.0);
  EXPECT_FALSE(scale_of("1", silicone()));
  EXPECT_FALSE(scale_of("degC", silicone()));
}

TEST(ScaledValue, EveryUnitMistakeIsRefusedNamingTheText) {
  const Scale length = *scale_of("R", silicone());
  EXPECT_NE(message("2kPa", length).find("'kPa' is a pressure, not a length"), std::string::npos);
  EXPECT_NE(message("2parsec", length).find("'parsec' is not a length unit; valid: m, mm, um or nm"),
            std::string::npos);
  EXPECT_NE(message("um", length).find("'um' is not a number"), std::string::npos);
  const Scale unknown = *scale_of("R", PhysicalScales{});
  EXPECT_NE(message("150um", unknown).find("needs R"), std::string::npos);
  EXPECT_EQ(read_scaled("3", unknown), 3.0);  // a bare number needs no scale
  EXPECT_NE(message("1min", *scale_of("T_eps", PhysicalScales{})).find("needs a material"), std::string::npos);
}

TEST(ScaledValue, TheLengthScaleNeedsAPositiveLengthWithAUnit) {
  EXPECT_EQ(read_length_scale("50um").number, 50.0);
  EXPECT_EQ(read_length_scale("0.05 mm").unit->name, "mm");
  for (const char* bad : {"50", "-50um", "0um", "50kPa", "um"}) {
    EXPECT_THROW(read_length_scale(bad), std::invalid_argument) << bad;
  }
}

TEST(ScaledValue, AnAxisReadsUnitsInListsAndFunctions) {
  const Scale length = *scale_of("R", silicone());
  EXPECT_EQ(read_scaled_axis("1um, 2um, 3um", false, length).values, (std::vector<double>{0.02, 0.04, 0.06}));
  EXPECT_EQ(read_scaled_axis("1 um 2 um", false, length).values, (std::vector<double>{0.02, 0.04}));
  EXPECT_EQ(read_scaled_axis("linspace(1um, 3um, 3)", false, length).values,
            (std::vector<double>{0.02, 0.04, 0.06}));
  EXPECT_EQ(read_scaled_axis("0, 2um", false, length).values, (std::vector<double>{0.0, 0.04}));  // 0 needs no unit
  EXPECT_EQ(read_scaled_axis("0.02, 0.04", false, length).values, (std::vector<double>{0.02, 0.04}));
  EXPECT_THROW(read_scaled_axis("0.02, 2um", false, length), std::invalid_argument);  // mixed
  const Scale pressure = *scale_of("E0/(1-nu^2)", silicone());
  EXPECT_THROW(read_scaled_axis("1e-4, 2e-4", false, pressure, true), std::invalid_argument);  // a unit required
  const map::Axis kPa = read_scaled_axis("logspace(1kPa, 100kPa, 3)", false, pressure, true);
  EXPECT_TRUE(kPa.log_spaced);
  EXPECT_EQ(kPa.values.front(), 1000.0 / 4.0e6);
  EXPECT_EQ(kPa.values.back(), 100000.0 / 4.0e6);
  EXPECT_NEAR(kPa.values[1], 10000.0 / 4.0e6, 1e-15);
}

TEST(ScaledValue, PhysicalUnitsOfTheOutputs) {
  const PhysicalScales scales = silicone();
  EXPECT_EQ(physical_unit("R", scales)->units, "um");
  EXPECT_EQ(physical_unit("R", scales)->per_scaled, 50.0);
  EXPECT_EQ(physical_unit("E0/(1-nu^2)", scales)->units, "Pa");
  EXPECT_EQ(physical_unit("E0/(1-nu^2)", scales)->per_scaled, 4.0e6);
  // A load R^2 E0*: (50e-6 m)^2 x 4e6 Pa = 1e-2 N.
  EXPECT_EQ(physical_unit("R^2 E0/(1-nu^2)", scales)->units, "N");
  EXPECT_NEAR(physical_unit("R^2 E0/(1-nu^2)", scales)->per_scaled, 1e-2, 1e-17);
  EXPECT_EQ(physical_unit("T_eps", scales)->units, "s");
  EXPECT_FALSE(physical_unit("1", scales));
  PhysicalScales no_R = scales;
  no_R.R.reset();
  EXPECT_FALSE(physical_unit("R", no_R));
  EXPECT_FALSE(physical_unit("R^2 E0/(1-nu^2)", no_R));
}

}  // namespace
}  // namespace punchsweep::input
