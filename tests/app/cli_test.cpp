#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "model/point/point_evaluation.hpp"
#include "model/paper/single_level.hpp"
#include "model/laws/standard_linear_solid.hpp"

namespace {

struct CliRun {
  int exit_code;
  std::string out;
  std::string err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Runs the real binary the way a user would.
CliRun run_cli(const std::string& args) {
  // One file pair per test: ctest runs tests in parallel processes.
  const std::string stem = ::testing::TempDir() + "/punchsweep_cli_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string out = stem + ".out";
  const std::string err = stem + ".err";
  const std::string command = std::string(PUNCHSWEEP_BINARY) + " " + args + " >" + out + " 2>" + err;
  const int status = std::system(command.c_str());
  return CliRun{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

const std::string kGood = "--l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2";

// Bad input: exit 2, nothing on stdout, one stderr line naming the option and its range.
void expect_refused_command(const std::string& args, const std::string& option, const std::string& range) {
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_EQ(r.out, "") << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(range), std::string::npos) << r.err;
}

void expect_refused(const std::string& args, const std::string& option, const std::string& range) {
  expect_refused_command("point " + args, option, range);
}

double json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  EXPECT_NE(at, std::string::npos) << key;
  return std::strtod(json.c_str() + at + key.size() + 4, nullptr);
}

}  // namespace

TEST(Cli, negative_pitch_is_refused) { expect_refused("--l -0.5 --dh 0.075 --T 2.5 --pbar 0.06 --s 2", "--l", "l > 0"); }
TEST(Cli, zero_pitch_is_refused) { expect_refused("--l 0 --dh 0.075 --T 2.5 --pbar 0.06 --s 2", "--l", "l > 0"); }
TEST(Cli, creep_ratio_below_one_is_refused) { expect_refused("--l 0.75 --dh 0.075 --T 0.9 --pbar 0.06 --s 2", "--T", ">= 1"); }
TEST(Cli, shape_exponent_zero_is_refused) { expect_refused("--l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 0", "--s", "integer in [1, 32]"); }
TEST(Cli, fractional_shape_exponent_is_refused) { expect_refused("--l 0.75 --dh 0.075 --T 2.5 --pbar 0.06 --s 2.5", "--s", "integer in [1, 32]"); }
TEST(Cli, negative_height_difference_is_refused) { expect_refused("--l 0.75 --dh -0.01 --T 2.5 --pbar 0.06 --s 2", "--dh", "dh >= 0"); }
TEST(Cli, zero_pressure_is_refused) { expect_refused("--l 0.75 --dh 0.075 --T 2.5 --pbar 0 --s 2", "--pbar", "pbar > 0"); }
TEST(Cli, negative_pressure_is_refused) { expect_refused("--l 0.75 --dh 0.075 --T 2.5 --pbar -0.01 --s 2", "--pbar", "pbar > 0"); }
TEST(Cli, non_numeric_value_is_refused) { expect_refused("--l abc --dh 0.075 --T 2.5 --pbar 0.06 --s 2", "--l", "l > 0"); }
TEST(Cli, negative_time_is_refused) { expect_refused(kGood + " --times 0,-1", "--times", "t >= 0"); }
TEST(Cli, times_must_increase_strictly_and_have_no_empty_item_as_in_a_sweep) {
  for (const char* times : {"0,2,1", "0,1,1", "0,1,", "0,,1", ",0"}) {
    expect_refused(kGood + " --times " + times, "--times", "strictly increasing");
  }
  const CliRun r = run_cli("point " + kGood + " --times 'linspace(0, 2, 5)' --format csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\n1.5,"), std::string::npos) << "linspace() is accepted as in a sweep";
}
TEST(Cli, a_point_beyond_double_precision_is_flagged_not_valid) {
  for (const char* localization : {"paper", "refined"}) {
    const CliRun r = run_cli("point --l 1e308 --dh 0.05 --T 2.5 --pbar 0.06 --s 2 --format json --localization " +
                             std::string(localization));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("\"h_0\": null"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"valid\": false"), std::string::npos) << r.out;
    // The paper's closed forms overflow; the refined model finds no admissible state.
    EXPECT_NE(r.out.find(std::string(localization) == "paper" ? "not finite" : "no admissible solution"),
              std::string::npos)
        << r.out;
  }
}
TEST(Cli, stray_argument_is_named) {
  const CliRun r = run_cli("point " + kGood + " extra");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("unexpected argument 'extra'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(see punchsweep point --help)"), std::string::npos) << r.err;
}
TEST(Cli, missing_option_is_refused) { expect_refused("--l 0.75 --dh 0.075 --pbar 0.06 --s 2", "--T", ">= 1"); }
TEST(Cli, unknown_format_is_refused) { expect_refused(kGood + " --format xml", "--format", "table, json, csv"); }

TEST(Cli, unknown_option_is_refused) {
  const CliRun r = run_cli("point " + kGood + " --bogus 3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("unknown option --bogus"), std::string::npos) << r.err;
}

TEST(Cli, unknown_command_is_refused) {
  const CliRun r = run_cli("sweeep");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown command"), std::string::npos);
}

TEST(Cli, help_names_every_option_with_its_unit_and_range) {
  const CliRun r = run_cli("point --help");
  EXPECT_EQ(r.exit_code, 0);
  // The help wraps long lines: compare with runs of whitespace as one space.
  std::string flat;
  for (const char c : r.out) {
    const bool space = c == ' ' || c == '\n';
    if (!space || (!flat.empty() && flat.back() != ' ')) flat += space ? ' ' : c;
  }
  for (const char* text : {"--l", "in R", "l > 0", "--dh", "dh >= 0", "--T", "T >= 1", "--pbar",
                           "pbar > 0", "--s", "[1, 32]", "--C", "C > 0", "--times", "in T_eps",
                           "--format", "table, json or csv"}) {
    EXPECT_NE(flat.find(text), std::string::npos) << text;
  }
}

TEST(Cli, json_output_has_the_contract_keys_and_the_model_numbers) {
  // The default is the periodic model, which names itself first, as refined does.
  const CliRun periodic = run_cli("point " + kGood + " --format json");
  ASSERT_EQ(periodic.exit_code, 0) << periodic.err;
  EXPECT_EQ(periodic.out.rfind("{\n  \"localization\": \"periodic\",\n  \"regime\": ", 0), 0u) << periodic.out;
  const CliRun refined = run_cli("point " + kGood + " --format json --localization refined");
  ASSERT_EQ(refined.exit_code, 0) << refined.err;
  EXPECT_EQ(refined.out.rfind("{\n  \"localization\": \"shells:200\",\n  \"regime\": ", 0), 0u) << refined.out;
  // The paper's model: its numbers (docs/model.md, section 9), and no localization key.
  const CliRun r = run_cli("point " + kGood + " --format json --localization paper");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("localization"), std::string::npos) << r.out;
  for (const char* key : {"\"regime\": \"delayed\"", "\"t_star\": ", "\"h_0\": ", "\"h_inf\": ",
                          "\"valid\": true", "\"reason\": \"\"", "\"a1_inf\": ", "\"a2_inf\": ",
                          "\"area_fraction_inf\": ", "\"series\": {", "\"t\": [0, 0.5, 1, 2, 5]",
                          "\"a1\": [", "\"a2\": [", "\"P1\": [", "\"P2\": [", "\"area_fraction\": ["}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  }
  EXPECT_NEAR(json_number(r.out, "t_star"), 1.027595, 1e-6);  // docs/model.md, section 9
  EXPECT_NEAR(json_number(r.out, "h_0"), 0.0537767, 1e-7);
  EXPECT_NEAR(json_number(r.out, "h_inf"), 0.0842487, 1e-7);
  // Printed with round-trip precision: equal to the library's own value.
  using namespace punchsweep::model;
  const PointResult direct = evaluate_point(ContactProblem{0.75, 0.075, 0.06, Shape{2, 0.5}},
                                            StandardLinearSolid(2.5));
  EXPECT_EQ(json_number(r.out, "a1_inf"), direct.a1_inf);
}

TEST(Cli, never_regime_prints_null_t_star) {
  const CliRun r = run_cli("point --l 0.75 --dh 0.1 --T 2.5 --pbar 0.06 --s 2 --format json");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("\"regime\": \"never\""), std::string::npos);
  EXPECT_NE(r.out.find("\"t_star\": null"), std::string::npos);
}

TEST(Cli, flagged_point_reports_reason) {
  // Spots that merge: the localization models flag the point, the periodic model (the
  // default) solves it.
  const std::string merged = "point --l 0.3 --dh 0.2 --T 5 --pbar 0.3 --s 2 --format json";
  const CliRun r = run_cli(merged + " --localization refined");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("\"valid\": false"), std::string::npos);
  EXPECT_NE(r.out.find("spots of one level merge"), std::string::npos);
  const CliRun periodic = run_cli(merged);
  ASSERT_EQ(periodic.exit_code, 0);
  EXPECT_NE(periodic.out.find("\"valid\": true"), std::string::npos) << periodic.out;
}

TEST(Cli, csv_and_table_show_the_series) {
  const CliRun csv = run_cli("point " + kGood + " --format csv --times 0,5");
  ASSERT_EQ(csv.exit_code, 0);
  EXPECT_NE(csv.out.find("t,a1,a2,P1,P2,area_fraction\n0,"), std::string::npos) << csv.out;
  EXPECT_NE(csv.out.find("# regime = delayed"), std::string::npos);
  const CliRun table = run_cli("point " + kGood);
  ASSERT_EQ(table.exit_code, 0);
  EXPECT_NE(table.out.find("regime              delayed"), std::string::npos);
  EXPECT_NE(table.out.find("t [T_eps]"), std::string::npos);
}

namespace {

std::vector<double> json_array_of(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": [");
  EXPECT_NE(at, std::string::npos) << key;
  std::vector<double> values;
  const char* p = json.c_str() + at + key.size() + 5;
  while (*p != ']') {
    char* end = nullptr;
    values.push_back(std::strtod(p, &end));
    p = end;
    while (*p == ',' || *p == ' ') ++p;
  }
  return values;
}

}  // namespace

TEST(Cli, elastic_command_reproduces_table_9_1) {
  const CliRun r = run_cli("elastic --l 0.75 --dh 0.05 --pbar 0.06 --s 2 --E 1,0.8,0.5,0.4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Table 9.1, +-1 in the last printed digit.
  const std::vector<double> P1{0.0335, 0.0327, 0.0308, 0.0300}, a2{0.0567, 0.0926, 0.1455, 0.1662},
      A1{0.9454, 0.9432, 0.9379, 0.9355};
  const auto p1 = json_array_of(r.out, "P1"), got_a2 = json_array_of(r.out, "a2"), got_A1 = json_array_of(r.out, "A1");
  ASSERT_EQ(p1.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(p1[i], P1[i], 1e-4);
    EXPECT_NEAR(got_a2[i], a2[i], 1e-4);
    EXPECT_NEAR(got_A1[i], A1[i], 1e-4);
  }
  const CliRun md = run_cli("elastic --l 0.75 --dh 0.05 --pbar 0.06 --s 2 --E 0.8 --format markdown");
  EXPECT_NE(md.out.find("| 0.8 | 0.0327 | 0.0011 | 0.2976 | 0.0926 |"), std::string::npos) << md.out;
}

TEST(Cli, single_level_command_gives_fig_9_2_and_9_3_curves) {
  const CliRun r = run_cli("single-level --l 0.5 --s 3 --C 1 --a1-points 201");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a1 = json_array_of(r.out, "a1"), h = json_array_of(r.out, "h"), rate = json_array_of(r.out, "dh_da1");
  ASSERT_EQ(a1.size(), 201u);
  EXPECT_DOUBLE_EQ(a1.back(), 0.25);
  const double step = a1[1] - a1[0];
  for (std::size_t i = 1; i + 1 < a1.size(); ++i) {
    EXPECT_GT(h[i + 1], h[i]);  // Fig. 9.2a: increasing
    EXPECT_GT(rate[i], 0.0);    // Fig. 9.2b: positive slope
    if (i < 2 || i + 2 >= a1.size()) continue;
    // The slope is the derivative of the curve (five-point difference, fourth order).
    const double fd = (-h[i + 2] + 8 * h[i + 1] - 8 * h[i - 1] + h[i - 2]) / (12 * step);
    EXPECT_NEAR(rate[i], fd, 1e-6 * rate[i] + 1e-9) << "a1 = " << a1[i];
  }
  const CliRun t = run_cli("single-level --l 0.75 --s 2 --pbar 0.01 --T 5 --times 0,0.908824,50");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const auto ht = json_array_of(t.out.substr(t.out.find("\"series\"")), "h");
  EXPECT_NEAR(ht[0], 0.0203224, 5e-8);  // h(0), docs/model.md, section 9
  EXPECT_NEAR(ht[1], 0.04, 1e-6);       // h(t*) = dh = 0.04 at t* = 0.908824
  EXPECT_NEAR(ht[2], 0.0490070, 5e-8);  // h(inf)
  EXPECT_NEAR(json_number(t.out, "h_inf"), 0.0490070, 5e-8);
}

TEST(Cli, new_commands_refuse_bad_input) {
  expect_refused_command("elastic --l 0.75 --dh 0.05 --pbar 0.06 --s 2 --E 1,-1", "--E", "E > 0");
  expect_refused_command("single-level --l 0.75 --s 0", "--s", "[1, 32]");
  expect_refused_command("single-level --l 0.75 --s 2 --pbar 0.01 --T 0.5", "--T", ">= 1");
}

TEST(Cli, reference_command_solves_a_point_on_a_grid) {
  // The paper's Fig. 9.5b points on a coarse grid: the regimes of the full solution.
  for (const auto& [dh, regime] : {std::pair{"0.05", "immediate"}, {"0.075", "delayed"}, {"0.1", "never"}}) {
    const CliRun r = run_cli(std::string("reference --l 0.75 --dh ") + dh + " --T 2.5 --pbar 0.06 --s 2 --bem-grid 48");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(std::string("\"regime\": \"") + regime + "\""), std::string::npos) << dh;
    const auto P1 = json_array_of(r.out, "P1"), P2 = json_array_of(r.out, "P2");
    for (std::size_t i = 0; i < P1.size(); ++i) EXPECT_NEAR(P1[i] + P2[i], 0.06 * 0.75 * 0.75, 1e-12);
  }
  expect_refused_command("reference --l 0.75 --dh 0.05 --T 2.5 --pbar 0.06 --s 2 --bem-grid 33", "--bem-grid", "even");
}

// Material files (docs/materials.md): the point takes --material, its
// temperature and a ramp; bad files and values are refused like any bad input.
TEST(Cli, material_point_runs_and_states_its_units) {
  const std::string material = std::string(PUNCHSWEEP_SOURCE_DIR) + "/materials/nbr_linder2011.ini";
  const CliRun r = run_cli("point --material " + material + " --l 0.75 --dh 0.02 --pbar 0.005 --s 2 --ramp 20");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("time in s"), std::string::npos) << r.out;
  // E0* = (1200 + 1607.1 + 228.6 + 361.5 + 63.9 + 68.7) kPa / (1 - 0.5^2), from the file.
  EXPECT_NE(r.out.find("E0* = E0/(1-nu^2) = 4.7064e+06 Pa"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ramp_time = 20 s"), std::string::npos) << r.out;
  // Under a ramp the surface is unloaded at t = 0, and the table says why h_0 is 0.
  EXPECT_NE(r.out.find("h_0                 0 R (unloaded at t = 0: the load rises from 0)"), std::string::npos)
      << r.out;
  const CliRun step = run_cli("point --material " + material + " --l 0.75 --dh 0.02 --pbar 0.005 --s 2");
  EXPECT_EQ(step.out.find("unloaded at t = 0"), std::string::npos) << step.out;
}

TEST(Cli, material_inputs_are_refused_with_their_range) {
  const std::string dir = ::testing::TempDir();
  const std::string wlf = dir + "/punchsweep_cli_wlf.ini";
  std::ofstream(wlf) << "[material]\nname = test, made up\nlaw = prony\nmodulus_unit = MPa\ntime_unit = s\n"
                        "poisson = 0.4\nE_inf = 1\nE_i = 2\ntau_i = 1\n[shift]\nkind = wlf\nC1 = 17.44\n"
                        "C2 = 51.6\nT_ref = 105\n";
  const std::string bad = dir + "/punchsweep_cli_bad.ini";
  std::ofstream(bad) << "[material]\nname = bad\nlaw = prony\nmodulus_unit = MPa\ntime_unit = s\n"
                        "poisson = 0.4\nE_inf = -1\nE_i = 2\ntau_i = 1\n";
  const std::string point = " --l 0.75 --dh 0.05 --pbar 0.03 --s 2";
  expect_refused("--material " + wlf + point + " --temperature 40", "--temperature = 40", "temperature > 61.0626703");
  // Issue 22: just above WLF's divergence (T_ref - C2 = 53.4) a_T overflows; refused by the
  // option's own name and range, not "--time-temperature".
  expect_refused("--material " + wlf + point + " --temperature 54", "--temperature = 54", "temperature > 61.0626703");
  expect_refused("--material " + wlf + point + " --temperature 61", "--temperature = 61",
                 "the shift a_T exceeds 1e100 on its way to WLF's divergence at T_ref - C2 = 53.4");
  expect_refused("--material " + bad + point, "E_inf = -1", "E_inf > 0");
  expect_refused("--material " + dir + "/no_such_file.ini" + point, "--material", "does not exist");
  // Not regular files: a device is not read without end, a folder is named as one.
  expect_refused("--material /dev/zero" + point, "--material = material file /dev/zero", "not a regular file");
  expect_refused("--material " + dir + point, "--material = material file " + dir, "is a folder");
  const std::string binary = dir + "/punchsweep_cli_binary.ini";
  std::ofstream(binary) << "[material]\nname = x\n\x01\x02\xff\xfe\n";
  expect_refused("--material " + binary + point, "line 3: byte 0x01 is a control character", "INI text");
  // Issue 24: a law's parameter beside --material says whose it is and what the file takes.
  expect_refused("--material " + wlf + point + " --T 2",
                 "unknown option --T (creep ratio T_eps/T_sigma) of the standard_linear_solid law",
                 "with --material the law is the file's, which takes --temperature");
  expect_refused(point + " --T 2 --temperature 40", "unknown option --temperature",
                 "(a material's temperature: give --material FILE");
  const std::string no_shift = std::string(PUNCHSWEEP_SOURCE_DIR) + "/materials/silicone_elite_double32.ini";
  expect_refused("--material " + no_shift + point + " --temperature 40", "unknown option --temperature",
                 "this material file has no [shift], so its law takes no temperature");
  expect_refused("--material " + wlf + point + " --ramp -1", "--ramp", "t_r >= 0");
  expect_refused("--material " + wlf + point + " --load-table '0:0, 5:0.9, 6:0.5, 9:1'", "--load-table",
                 "does not recede");
  expect_refused_command("reference --material " + wlf + point + " --temperature 40 --bem-grid 32",
                         "--temperature = 40", "temperature > 61.0626703");
}

// --pressure 23.532kPa is pbar = 23532 Pa / E0*, E0* = 3529.8 kPa / 0.75 from the file: 0.005.
TEST(Cli, physical_pressure_is_pbar_times_the_plane_strain_modulus) {
  const std::string material = std::string(PUNCHSWEEP_SOURCE_DIR) + "/materials/nbr_linder2011.ini";
  const std::string point = "point --material " + material + " --l 0.75 --dh 0.02 --s 2 --format json";
  const CliRun kpa = run_cli(point + " --pressure 23.532kPa");
  const CliRun pbar = run_cli(point + " --pbar 0.005");
  ASSERT_EQ(kpa.exit_code, 0) << kpa.err;
  ASSERT_EQ(pbar.exit_code, 0) << pbar.err;
  EXPECT_NEAR(json_number(kpa.out, "t_star"), json_number(pbar.out, "t_star"), 1e-9 * json_number(pbar.out, "t_star"));
  expect_refused("--material " + material + " --l 0.75 --dh 0.02 --s 2 --pressure 23", "--pressure", "kPa");
  expect_refused("--material " + material + " --l 0.75 --dh 0.02 --s 2 --pressure 23kPa --pbar 0.005", "--pressure",
                 "one of them");
  expect_refused("--l 0.75 --dh 0.02 --T 2.5 --s 2 --pressure 23kPa", "--pressure", "needs --material");
}

// single-level under a ramp on the standard linear solid: a1(t) is the single-level radius at
// X = pbar0 g(t), g the ramp's closed form (T t + (T - 1)(e^-t - 1))/t_r before t_r and
// T - (T - 1) e^-t (e^t_r - 1)/t_r after it.
TEST(Cli, single_level_under_an_sls_ramp_follows_its_closed_form) {
  const CliRun r = run_cli("single-level --l 0.75 --s 2 --pbar 0.02 --T 2.5 --ramp 2 --times 0.5,2,6 "
                           "--a1-points 2 --format csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double T = 2.5, t_r = 2.0;
  const punchsweep::model::SingleLevel single(0.75, punchsweep::model::Shape{2, 0.5});
  std::istringstream lines(r.out.substr(r.out.find("t,a1,h\n") + 7));
  for (const double t : {0.5, 2.0, 6.0}) {
    double time = 0.0, a1 = 0.0;
    char comma = 0;
    lines >> time >> comma >> a1;
    lines.ignore(1000, '\n');
    const double g = t <= t_r ? (T * t + (T - 1.0) * std::expm1(-t)) / t_r
                              : T - (T - 1.0) * std::exp(-t) * std::expm1(t_r) / t_r;
    EXPECT_EQ(time, t);
    EXPECT_NEAR(a1, single.contact_radius(0.02 * g), 1e-13) << "t = " << t;
  }
}

// Issue 24: `sweep --help` said the temperature defaults to 20 while a material's run takes
// its shift's T_ref (65 C for the PLA file, from its [shift] T_ref = 65).
TEST(Cli, sweep_help_states_the_materials_reference_temperature_as_the_default) {
  const CliRun help = run_cli("sweep --help");
  EXPECT_EQ(help.exit_code, 0);
  const std::size_t at = help.out.find("--grid.temperature");
  ASSERT_NE(at, std::string::npos);
  std::string entry = help.out.substr(at, help.out.find("--grid.", at + 5) - at);
  std::string words;  // the entry with its line breaks and indentation as single spaces
  for (const char c : entry) {
    if (c == '\n' || c == ' ') {
      if (!words.empty() && words.back() != ' ') words += ' ';
    } else {
      words += c;
    }
  }
  EXPECT_NE(words.find("default the material's reference temperature (its [shift] T_ref)"), std::string::npos) << words;
  EXPECT_EQ(words.find("default 20"), std::string::npos) << words;
  const std::string pla = std::string(PUNCHSWEEP_SOURCE_DIR) + "/materials/pla_prusament_chapuis2025.ini";
  const CliRun dry = run_cli("sweep --dry-run --model.material " + pla +
                             " --grid.l 0.75 --grid.dh 0.05 --grid.pbar 0.01 --grid.s 2");
  EXPECT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(dry.out.find("temperature    1 values  65 "), std::string::npos) << dry.out;
}

// Issue 24: lengths and pressures in the user's units. With --R (the punch size and its
// unit) --l and --dh take a length unit, and with a material --pbar takes a pressure unit;
// each is its scaled value, the same point as the bare numbers.
TEST(Cli, lengths_and_pressures_with_units_are_the_scaled_point) {
  char dh[64];
  std::snprintf(dh, sizeof dh, "%.17g", 2.0 / 50.0);  // the scaled value, worked out here
  const std::string rest = " --T 2.5 --pbar 0.06 --s 2 --format json";
  const CliRun physical = run_cli("point --R 50um --l 150um --dh 2um" + rest);
  const CliRun scaled = run_cli(std::string("point --l 3 --dh ") + dh + rest);
  ASSERT_EQ(physical.exit_code, 0) << physical.err;
  // The scaled fields are the scaled point's; "physical" and "units" follow them.
  const auto scaled_part = [](const std::string& json) {
    return json.substr(0, std::min(json.find(",\n  \"physical\""), json.rfind("\n}")));
  };
  EXPECT_EQ(scaled_part(physical.out), scaled_part(scaled.out));
  EXPECT_EQ(scaled.out.find("\"physical\""), std::string::npos);
  EXPECT_NE(physical.out.find("\"physical\": {\n    \"R\": 50,\n    \"l\": 150,\n    \"dh\": 2,"), std::string::npos)
      << physical.out;
  EXPECT_NE(physical.out.find("\"units\": {\n    \"R\": \"um\",\n    \"l\": \"um\",\n    \"dh\": \"um\","),
            std::string::npos);
  // R in mm and the lengths in um (0.05 mm is 50 um exactly), and the table's echo in R's unit.
  const CliRun in_mm = run_cli("point --R 0.05mm --l 150um --dh 2um" + rest);
  EXPECT_EQ(scaled_part(in_mm.out), scaled_part(scaled.out));
  EXPECT_NE(in_mm.out.find("\"R\": 0.05,\n    \"l\": 0.15,\n    \"dh\": 0.002,"), std::string::npos) << in_mm.out;
  const CliRun table = run_cli("point --R 0.05mm --l 150um --dh 2um --T 2.5 --pbar 0.06 --s 2");
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("l = 3 R (0.15 mm)"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("R = 0.05 mm"), std::string::npos) << table.out;
  // --pbar in kPa with a material is --pressure's point.
  const std::string nbr = std::string(PUNCHSWEEP_SOURCE_DIR) + "/materials/nbr_linder2011.ini";
  const std::string point = "point --material " + nbr + " --l 0.75 --dh 0.02 --s 2 --format json";
  const CliRun kpa = run_cli(point + " --pbar 20kPa");
  ASSERT_EQ(kpa.exit_code, 0) << kpa.err;
  EXPECT_EQ(kpa.out, run_cli(point + " --pressure 20kPa").out);
  // Refused, naming what is missing or wrong.
  expect_refused("--l 150um --dh 0.02 --T 2.5 --pbar 0.06 --s 2", "--l = '150um'", "needs R");
  expect_refused("--R 50 --l 0.75 --dh 0.02 --T 2.5 --pbar 0.06 --s 2", "--R = '50'", "has no unit");
  expect_refused("--R 50kPa --l 0.75 --dh 0.02 --T 2.5 --pbar 0.06 --s 2", "--R", "is a pressure, not a length");
  expect_refused("--R 50um --l 150kPa --dh 0.02 --T 2.5 --pbar 0.06 --s 2", "--l", "is a pressure, not a length");
  expect_refused("--l 0.75 --dh 0.02 --T 2.5 --pbar 20kPa --s 2", "--pbar = '20kPa'", "needs a material");
  expect_refused("--R 50um --l -150um --dh 0.02 --T 2.5 --pbar 0.06 --s 2", "--l = -150um", "l > 0");
}
