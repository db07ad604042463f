#include "input/sweep_options.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "input/usage_error.hpp"
#include "run/resume_policy.hpp"

namespace {

using punchsweep::run::identity_differences;
using punchsweep::input::parse_sweep_options;
using punchsweep::input::UsageError;
using punchsweep::map::Quantities;
using punchsweep::sweep::ReferenceMethod;
using punchsweep::sweep::SweepConfig;

SweepConfig parse(const std::vector<std::string>& args) {
  std::ostringstream help;
  bool help_shown = true;
  const SweepConfig config = parse_sweep_options(args, help, &help_shown);
  EXPECT_FALSE(help_shown);
  EXPECT_EQ(help.str(), "");
  return config;
}

// The UsageError message for `args`; fails the test when they are accepted.
std::string refusal(const std::vector<std::string>& args) {
  try {
    parse(args);
    ADD_FAILURE() << "accepted";
  } catch (const UsageError& e) {
    return e.what();
  }
  return {};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A config file in the test's own temporary path (ctest runs tests in parallel).
std::string write_ini(const std::string& text, const std::string& suffix = "") {
  const std::string path = ::testing::TempDir() + "/punchsweep_config_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + suffix + ".ini";
  std::ofstream(path) << text;
  return path;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SweepOptions, defaults_give_the_documented_grid) {
  const SweepConfig c = parse({});
  const auto& axes = c.grid.axes;
  EXPECT_EQ(axes[0].text, "linspace(0.5, 1.25, 7)");
  EXPECT_EQ(axes[1].text, "linspace(0.01, 0.12, 23)");
  EXPECT_EQ(axes[2].text, "linspace(2, 10, 9)");
  EXPECT_EQ(axes[3].text, "logspace(0.005, 0.08, 24)");
  EXPECT_EQ(axes[4].text, "1, 2, 3");
  EXPECT_EQ(c.grid.shape(), (punchsweep::map::Index{7, 23, 9, 24, 3}));
  EXPECT_EQ(c.grid.points(), 104328u);  // 7 x 23 x 9 x 24 x 3: "about 10^5"
  // The paper's pitches are grid values: 0.5, 0.75, 1.0, 1.25.
  EXPECT_EQ(axes[0].values, (std::vector<double>{0.5, 0.625, 0.75, 0.875, 1.0, 1.125, 1.25}));
  EXPECT_EQ(axes[0].values.front(), 0.5);
  EXPECT_EQ(axes[0].values.back(), 1.25);
  EXPECT_EQ(axes[1].values.front(), 0.01);
  EXPECT_EQ(axes[1].values.back(), 0.12);
  EXPECT_EQ(axes[2].values, (std::vector<double>{2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(axes[3].values.front(), 0.005);
  EXPECT_EQ(axes[3].values.back(), 0.08);
  EXPECT_TRUE(axes[3].log_spaced);
  EXPECT_FALSE(axes[0].log_spaced);
  EXPECT_EQ(axes[4].values, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(c.C, 0.5);
  EXPECT_EQ(c.creep_law->name, "standard_linear_solid");
  EXPECT_EQ(c.times, (std::vector<double>{0, 0.5, 1, 2, 5}));
  EXPECT_EQ(c.output, "regime_map.h5");
  EXPECT_EQ(c.quantities, Quantities::full);
  EXPECT_EQ(c.chunk, 4096u);
  EXPECT_FALSE(c.quiet);
  EXPECT_FALSE(c.resume);
  EXPECT_FALSE(c.overwrite);
  EXPECT_FALSE(c.dry_run);
  EXPECT_EQ(c.config_path, "");
  EXPECT_EQ(c.reference.method, ReferenceMethod::none);
  EXPECT_FALSE(c.reference.on());
  EXPECT_EQ(c.reference.grid, 128);
  EXPECT_FALSE(c.reference.sample.has_value());  // all points
  EXPECT_EQ(c.reference.seed, 1u);
}

TEST(SweepOptions, help_explains_options_ranges_syntax_and_default_grid) {
  std::ostringstream out;
  bool help_shown = false;
  const SweepConfig c = parse_sweep_options({"--help"}, out, &help_shown);
  EXPECT_TRUE(help_shown);
  const std::string help = out.str();
  for (const char* part : {"usage: punchsweep sweep", "--config FILE.ini", "--output FILE.h5", "--resume",
                           "--overwrite", "--dry-run", "--quiet", "--quantities WHAT", "--chunk N",
                           "--grid.l AXIS", "--grid.pbar AXIS", "--model.creep_law", "--time.times",
                           "--run.overwrite", "in E0* = E0/(1-nu^2)", "an integer in [1, 32]",
                           "logspace(a, b, n)", "[grid]", "[run]", "pbar = logspace(0.005, 0.08, 32)",
                           "7 x 23 x 9 x 24 x 3 = 104328 points", "Keys the file leaves out keep their defaults",
                           "--reference METHOD", "--bem-grid N", "--reference.method METHOD", "--reference.grid N",
                           "--reference.sample K", "--reference.seed SEED", "an even integer in [16, 2048]",
                           "[reference]", "bem_regime", "not_computed"}) {
    EXPECT_TRUE(contains(help, part)) << part;
  }
  EXPECT_EQ(c.grid.points(), 0u);  // a default SweepConfig: nothing was resolved
}

TEST(SweepOptions, config_file_sets_its_keys_and_left_out_grid_keys_keep_defaults) {
  const std::string path = write_ini(
      "# a small map\n"
      "[grid]\n"
      "T = 2, 5, 10   # three creep ratios\n"
      "s = 2\n"
      "[model]\n"
      "C = 0.7\n"
      "creep_law = sls\n"
      "[time]\n"
      "times = linspace(0, 4, 5)\n"
      "[output]\n"
      "file = small.h5\n"
      "quantities = regime\n"
      "[run]\n"
      "chunk = 512\n"
      "quiet = yes\n"
      "overwrite = 1\n");
  const SweepConfig c = parse({"--config", path});
  EXPECT_EQ(c.config_path, path);
  EXPECT_EQ(c.grid.axes[2].values, (std::vector<double>{2, 5, 10}));
  EXPECT_EQ(c.grid.axes[4].values, std::vector<double>{2});
  EXPECT_EQ(c.grid.axes[0].text, "linspace(0.5, 1.25, 7)");
  EXPECT_EQ(c.grid.points(), 7u * 23u * 3u * 24u * 1u);
  EXPECT_EQ(c.C, 0.7);
  EXPECT_EQ(c.creep_law->name, "standard_linear_solid");
  EXPECT_EQ(c.times, (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_EQ(c.output, "small.h5");
  EXPECT_EQ(c.quantities, Quantities::regime);
  EXPECT_EQ(c.chunk, 512u);
  EXPECT_TRUE(c.quiet);
  EXPECT_TRUE(c.overwrite);
  EXPECT_FALSE(c.resume);
}

TEST(SweepOptions, command_line_beats_config_file) {
  const std::string path = write_ini("[grid]\nT = 2, 5, 10\n[output]\nfile = from_file.h5\n[run]\nchunk = 512\n");
  const SweepConfig c = parse({"--config", path, "--grid.T", "3", "--output", "cli.h5", "--run.chunk", "64"});
  EXPECT_EQ(c.grid.axes[2].values, std::vector<double>{3});
  EXPECT_EQ(c.output, "cli.h5");
  EXPECT_EQ(c.chunk, 64u);
}

TEST(SweepOptions, shortcuts_set_their_keys) {
  const SweepConfig c = parse({"--output", "x.h5", "--quantities", "regime", "--chunk", "12", "--resume",
                               "--quiet", "--dry-run"});
  EXPECT_EQ(c.output, "x.h5");
  EXPECT_EQ(c.quantities, Quantities::regime);
  EXPECT_EQ(c.chunk, 12u);
  EXPECT_TRUE(c.resume);
  EXPECT_FALSE(c.overwrite);
  EXPECT_TRUE(c.quiet);
  EXPECT_TRUE(c.dry_run);
  EXPECT_TRUE(parse({"--overwrite"}).overwrite);
}

TEST(SweepOptions, every_key_is_also_a_command_line_option) {
  const SweepConfig c = parse({"--grid.l", "1", "--grid.dh=0", "--grid.T", "linspace(1, 2, 3)", "--grid.pbar",
                               "0.01 0.02", "--grid.s", "4", "--model.C", "1.5", "--model.creep_law", "sls",
                               "--time.times", "0, 7", "--output.file", "y.h5", "--output.quantities", "regime",
                               "--run.chunk", "2048", "--run.quiet", "true", "--run.resume", "yes",
                               "--run.overwrite", "0", "--reference.method", "bem", "--reference.grid", "32",
                               "--reference.sample", "3", "--reference.seed", "0"});
  EXPECT_EQ(c.grid.axes[0].values, std::vector<double>{1});
  EXPECT_EQ(c.grid.axes[1].values, std::vector<double>{0});
  EXPECT_EQ(c.grid.axes[2].values, (std::vector<double>{1, 1.5, 2}));
  EXPECT_EQ(c.grid.axes[3].values, (std::vector<double>{0.01, 0.02}));
  EXPECT_EQ(c.grid.axes[4].values, std::vector<double>{4});
  EXPECT_EQ(c.C, 1.5);
  EXPECT_EQ(c.creep_law->name, "standard_linear_solid");
  EXPECT_EQ(c.times, (std::vector<double>{0, 7}));
  EXPECT_EQ(c.output, "y.h5");
  EXPECT_EQ(c.quantities, Quantities::regime);
  EXPECT_EQ(c.chunk, 2048u);
  EXPECT_TRUE(c.quiet);
  EXPECT_TRUE(c.resume);
  EXPECT_FALSE(c.overwrite);
  EXPECT_TRUE(c.reference.on());
  EXPECT_EQ(c.reference.grid, 32);
  EXPECT_EQ(c.reference.sample, 3u);
  EXPECT_EQ(c.reference.seed, 0u);
}

TEST(SweepOptions, reference_keys_come_from_the_file_and_the_shortcuts) {
  const std::string path = write_ini("[reference]\nmethod = bem\ngrid = 64\nsample = 500\nseed = 42\n");
  const SweepConfig from_file = parse({"--config", path});
  EXPECT_EQ(from_file.reference.method, ReferenceMethod::bem);
  EXPECT_EQ(from_file.reference.grid, 64);
  EXPECT_EQ(from_file.reference.sample, 500u);
  EXPECT_EQ(from_file.reference.seed, 42u);
  const SweepConfig shortcuts = parse({"--config", path, "--reference", "none", "--bem-grid", "2048",
                                       "--reference.sample", "all"});
  EXPECT_FALSE(shortcuts.reference.on());
  EXPECT_EQ(shortcuts.reference.grid, 2048);
  EXPECT_FALSE(shortcuts.reference.sample.has_value());
  EXPECT_EQ(shortcuts.reference.seed, 42u);
  EXPECT_EQ(parse({"--reference", "bem", "--bem-grid", "16"}).reference.grid, 16);
  const std::string both = refusal({"--reference", "bem", "--reference.method", "none", "--bem-grid", "32",
                                    "--reference.grid", "64"});
  EXPECT_TRUE(contains(both, "--reference and --reference.method")) << both;
  EXPECT_TRUE(contains(both, "--bem-grid and --reference.grid")) << both;
  const std::string unknown = refusal({"--reference.bogus", "1"});
  EXPECT_TRUE(contains(unknown, "method, grid, sample, seed")) << unknown;
}

TEST(SweepOptions, reference_sample_may_not_exceed_the_grid) {
  const std::vector<std::string> grid{"--grid.l", "0.5,1", "--grid.dh", "0.05", "--grid.T", "2,5",
                                      "--grid.pbar", "0.01,0.02,0.03", "--grid.s", "2"};  // 12 points
  std::vector<std::string> args = grid;
  args.insert(args.end(), {"--reference", "bem", "--reference.sample", "12"});
  EXPECT_EQ(parse(args).reference.sample, 12u);  // every point, drawn at random
  args.back() = "13";
  EXPECT_EQ(refusal(args),
            "reference.sample = 13: value 13 is more than the grid's 12 points; valid range: all, invalid, "
            "boundary, or an integer in [1, 12] (the grid's point count)");
  // The rules that pick points from the model's answers.
  args.back() = "invalid";
  EXPECT_EQ(parse(args).reference.rule, punchsweep::sweep::ReferenceConfig::SampleRule::invalid);
  EXPECT_FALSE(parse(args).reference.sample.has_value());
  EXPECT_NE(std::find(parse(args).identity.begin(), parse(args).identity.end(), "reference.sample = invalid"),
            parse(args).identity.end());
  args.back() = "boundary";
  EXPECT_EQ(parse(args).reference.rule, punchsweep::sweep::ReferenceConfig::SampleRule::boundary);
  args.back() = "12";
  EXPECT_EQ(parse(args).reference.rule, punchsweep::sweep::ReferenceConfig::SampleRule::count);
  // Checked whether or not the reference is on, like every other key.
  args = grid;
  args.insert(args.end(), {"--reference.sample", "100"});
  EXPECT_TRUE(contains(refusal(args), "reference.sample = 100: value 100 is more than the grid's 12 points"));
}

TEST(SweepOptions, shortcut_and_its_key_together_are_an_error_naming_both) {
  const std::string message = refusal({"--output", "a.h5", "--output.file", "b.h5"});
  EXPECT_TRUE(contains(message, "--output and --output.file")) << message;
  const std::string flags = refusal({"--quiet", "--run.quiet", "false", "--chunk", "1", "--run.chunk", "2"});
  EXPECT_TRUE(contains(flags, "--quiet and --run.quiet")) << flags;
  EXPECT_TRUE(contains(flags, "--chunk and --run.chunk")) << flags;
}

TEST(SweepOptions, unknown_key_in_config_file_is_an_error_naming_key_file_and_line) {
  const std::string path = write_ini("[grid]\nT = 2\nfoo = 1\n");
  const std::string message = refusal({"--config", path});
  EXPECT_TRUE(contains(message, "grid.foo")) << message;
  EXPECT_TRUE(contains(message, path + ", line 3")) << message;
}

TEST(SweepOptions, unknown_section_in_config_file_is_an_error_naming_it_and_the_file) {
  const std::string path = write_ini("[grid]\nT = 2\n[bogus]\n");
  const std::string message = refusal({"--config", path});
  EXPECT_TRUE(contains(message, "unknown section [bogus]")) << message;
  EXPECT_TRUE(contains(message, path)) << message;
}

TEST(SweepOptions, malformed_or_repeated_config_lines_are_errors_naming_the_line) {
  const std::string path = write_ini("[grid]\nT = 2\nT = 3\njust words\nl = 1\n");
  const std::vector<std::string> lines = lines_of(refusal({"--config", path}));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(contains(lines[0], "line 3: grid.T is set again (first on line 2)")) << lines[0];
  EXPECT_TRUE(contains(lines[1], "line 4: expected '[section]' or 'key = value'")) << lines[1];
  const std::string before_section = refusal({"--config", write_ini("T = 2\n", "_2")});
  EXPECT_TRUE(contains(before_section, "comes before any [section]")) << before_section;
}

TEST(SweepOptions, unknown_option_on_command_line_is_an_error_naming_it) {
  const std::string key = refusal({"--grid.foo", "1"});
  EXPECT_TRUE(contains(key, "--grid.foo")) << key;
  EXPECT_TRUE(contains(key, "l, dh, T, pbar, s")) << key;
  const std::string option = refusal({"--bogus"});
  EXPECT_TRUE(contains(option, "--bogus")) << option;
  // No abbreviations: the key names are the config file's vocabulary.
  EXPECT_TRUE(contains(refusal({"--grid.pb", "0.1"}), "--grid.pb"));
}

TEST(SweepOptions, missing_config_file_is_an_error_naming_the_path) {
  const std::string path = ::testing::TempDir() + "/punchsweep_config_no_such_file.ini";
  const std::string message = refusal({"--config", path});
  EXPECT_TRUE(contains(message, path)) << message;
  EXPECT_TRUE(contains(message, "does not exist")) << message;
}

TEST(SweepOptions, positional_argument_is_rejected) {
  EXPECT_TRUE(contains(refusal({"my.ini"}), "unexpected argument"));
}

TEST(SweepOptions, negative_numbers_are_read_as_values_not_options) {
  EXPECT_EQ(refusal({"--grid.dh", "-0.5"}),
            "grid.dh = -0.5: value -0.5 is outside its range; valid range: dh >= 0 (in R)");
}

struct BadValue {
  std::vector<std::string> args;
  std::string line_start;  ///< "KEY = VALUE: "
  std::string range;
};

TEST(SweepOptions, each_bad_value_gives_one_line_with_key_value_and_range) {
  const std::vector<BadValue> cases{
      {{"--grid.l", "-1"}, "grid.l = -1: ", "l > 0 (in R)"},
      {{"--grid.l", "0, 1"}, "grid.l = 0, 1: ", "l > 0 (in R)"},
      {{"--grid.dh", "-0.01, 0.1"}, "grid.dh = -0.01, 0.1: ", "dh >= 0 (in R)"},
      {{"--grid.T", "0.5, 2"}, "grid.T = 0.5, 2: value 0.5 is outside its range", "T >= 1 (T = T_eps/T_sigma)"},
      {{"--grid.pbar", "0"}, "grid.pbar = 0: ", "pbar > 0 (in E0* = E0/(1-nu^2))"},
      {{"--grid.pbar", "-0.1, 0.1"}, "grid.pbar = -0.1, 0.1: ", "pbar > 0"},
      {{"--grid.s", "0"}, "grid.s = 0: ", "an integer in [1, 32]"},
      {{"--grid.s", "2.5"}, "grid.s = 2.5: 2.5 is not an integer", "an integer in [1, 32]"},
      {{"--grid.s", "linspace(30, 34, 5)"}, "grid.s = linspace(30, 34, 5): values 33, 34 are outside",
       "an integer in [1, 32]"},
      {{"--model.C", "0"}, "model.C = 0: ", "C > 0"},
      {{"--model.C", "-1"}, "model.C = -1: ", "C > 0"},
      {{"--model.C", "half"}, "model.C = half: 'half' is not a finite number", "C > 0"},
      {{"--model.creep_law", "maxwell"}, "model.creep_law = maxwell: ", "standard_linear_solid (alias sls)"},
      {{"--time.times", "0, 2, 1"}, "time.times = 0, 2, 1: values must be strictly increasing (1 follows 2)",
       "each t >= 0 and finite, strictly increasing (in T_eps)"},
      {{"--time.times", "-1, 0"}, "time.times = -1, 0: value -1 is outside its range", "each t >= 0"},
      {{"--quantities", "both"}, "output.quantities = both: ", "regime or full"},
      {{"--output.file", ""}, "output.file = '': ", "a non-empty file name"},
      {{"--output", "a#b.h5"}, "output.file = a#b.h5: ", "a non-empty file name without '#'"},
      {{"--chunk", "0"}, "run.chunk = 0: ", "an integer >= 1"},
      {{"--chunk", "1.5"}, "run.chunk = 1.5: '1.5' is not an integer", "an integer >= 1"},
      {{"--run.resume", "maybe"}, "run.resume = maybe: ", "true, false, 1, 0, yes or no"},
      {{"--reference", "fem"}, "reference.method = fem: 'fem' is not one of none, bem", "none or bem"},
      {{"--bem-grid", "33"}, "reference.grid = 33: value 33 is outside its range", "an even integer in [16, 2048]"},
      {{"--bem-grid", "8"}, "reference.grid = 8: value 8 is outside its range", "an even integer in [16, 2048]"},
      {{"--reference.grid", "4096"}, "reference.grid = 4096: ", "an even integer in [16, 2048]"},
      {{"--reference.grid", "64.5"}, "reference.grid = 64.5: '64.5' is not a whole number",
       "an even integer in [16, 2048]"},
      {{"--reference.grid", "99999999999"}, "reference.grid = 99999999999: value 99999999999 is too large",
       "an even integer in [16, 2048]"},
      {{"--reference.sample", "0"}, "reference.sample = 0: value 0 is outside its range",
       "all, invalid, boundary, or an integer in [1, the grid's point count]"},
      {{"--reference.sample", "some"}, "reference.sample = some: 'some' is not a whole number",
       "all, invalid, boundary, or an integer in [1, the grid's point count]"},
      {{"--reference.sample", "-5"}, "reference.sample = -5: ", "all, invalid, boundary, or an integer in [1,"},
      {{"--reference.seed", "-1"}, "reference.seed = -1: '-1' is not a whole number",
       "an integer in [0, 9223372036854775807]"},
      {{"--reference.seed", "9223372036854775808"}, "reference.seed = 9223372036854775808: value "
       "9223372036854775808 is too large (at most 9223372036854775807)", "an integer in [0, 9223372036854775807]"},
  };
  for (const BadValue& bad : cases) {
    const std::vector<std::string> lines = lines_of(refusal(bad.args));
    ASSERT_EQ(lines.size(), 1u) << bad.line_start;
    EXPECT_EQ(lines[0].rfind(bad.line_start, 0), 0u) << lines[0];
    EXPECT_TRUE(contains(lines[0], "; valid range: " + bad.range)) << lines[0];
  }
}

TEST(SweepOptions, bad_value_in_config_file_is_reported_like_one_on_the_command_line) {
  const std::string path = write_ini("[grid]\nT = 0.5, 2\n");
  EXPECT_EQ(refusal({"--config", path}),
            "grid.T = 0.5, 2: value 0.5 is outside its range; valid range: T >= 1 (T = T_eps/T_sigma)");
}

TEST(SweepOptions, several_bad_values_give_one_line_each_in_key_order) {
  const std::vector<std::string> lines = lines_of(refusal({"--grid.s", "0", "--grid.l", "-1", "--grid.T", "0.5",
                                                           "--model.C", "0", "--chunk", "0", "--time.times",
                                                           "1, 0"}));
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0].rfind("grid.l = -1:", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("grid.T = 0.5:", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("grid.s = 0:", 0), 0u) << lines[2];
  EXPECT_EQ(lines[3].rfind("model.C = 0:", 0), 0u) << lines[3];
  EXPECT_EQ(lines[4].rfind("time.times = 1, 0:", 0), 0u) << lines[4];
  EXPECT_EQ(lines[5].rfind("run.chunk = 0:", 0), 0u) << lines[5];
}

TEST(SweepOptions, grid_whose_point_count_overflows_is_refused) {
  const std::string big = "linspace(1, 2, 100000)";  // 1e20 points on four axes > 2^64
  const std::string message =
      refusal({"--grid.l", big, "--grid.dh", big, "--grid.T", big, "--grid.pbar", big});
  EXPECT_EQ(message.rfind("grid = 100000 x 100000 x 100000 x 100000 x 3 points: ", 0), 0u) << message;
  EXPECT_TRUE(contains(message, "does not fit in 64 bits")) << message;
}

TEST(SweepOptions, resolved_text_has_every_key_with_its_source) {
  const std::string path = write_ini("[grid]\nT = 2, 5, 10\n[model]\nC = 0.70\n");
  const SweepConfig c = parse({"--config", path, "--grid.s", "2", "--resume"});
  const std::string& text = c.resolved_text;
  for (const char* section : {"[grid]", "[model]", "[time]", "[output]", "[run]", "[reference]"}) {
    EXPECT_TRUE(contains(text, std::string("\n") + section + "\n")) << section;
  }
  EXPECT_TRUE(contains(text, "# default\nl = linspace(0.5, 1.25, 7)\n")) << text;
  EXPECT_TRUE(contains(text, "# from " + path + "\nT = 2, 5, 10\n")) << text;
  EXPECT_TRUE(contains(text, "# from " + path + "\nC = 0.7\n")) << text;
  EXPECT_TRUE(contains(text, "# from the command line\ns = 2\n")) << text;
  EXPECT_TRUE(contains(text, "# from the command line\nresume = true\n")) << text;
  for (const char* key : {"\nl = ", "\ndh = ", "\nT = ", "\npbar = ", "\ns = ", "\nC = ", "\ncreep_law = ",
                          "\ntimes = ", "\nfile = ", "\nquantities = ", "\nchunk = ", "\nquiet = ",
                          "\nresume = ", "\noverwrite = ", "\nmethod = none\n", "\ngrid = 128\n",
                          "\nsample = all\n", "\nseed = 1\n"}) {
    EXPECT_TRUE(contains(text, key)) << key;
  }
}

TEST(SweepOptions, resolved_text_reads_back_to_the_same_config) {
  const std::string path = write_ini("[grid]\nT = 2, 5, 10\ns = 2\n[time]\ntimes = 0 1 5\n[run]\nquiet = yes\n");
  const SweepConfig first = parse({"--config", path, "--grid.l", "linspace(0.6, 0.9, 4)", "--model.C", "0.25",
                                   "--output", "round.h5", "--quantities", "regime", "--chunk", "100",
                                   "--overwrite", "--reference", "bem", "--bem-grid", "048",
                                   "--reference.sample", "7", "--reference.seed", "00012"});
  const SweepConfig again = parse({"--config", write_ini(first.resolved_text, "_resolved")});
  for (std::size_t a = 0; a < first.grid.axes.size(); ++a) {
    EXPECT_EQ(again.grid.axes[a].values, first.grid.axes[a].values) << a;
    EXPECT_EQ(again.grid.axes[a].text, first.grid.axes[a].text) << a;
    EXPECT_EQ(again.grid.axes[a].log_spaced, first.grid.axes[a].log_spaced) << a;
  }
  EXPECT_EQ(again.C, first.C);
  EXPECT_EQ(again.creep_law, first.creep_law);
  EXPECT_EQ(again.times, first.times);
  EXPECT_EQ(again.output, first.output);
  EXPECT_EQ(again.quantities, first.quantities);
  EXPECT_EQ(again.chunk, first.chunk);
  EXPECT_EQ(again.quiet, first.quiet);
  EXPECT_EQ(again.resume, first.resume);
  EXPECT_EQ(again.overwrite, first.overwrite);
  EXPECT_EQ(again.reference.method, first.reference.method);
  EXPECT_EQ(again.reference.grid, 48);
  EXPECT_EQ(again.reference.sample, 7u);
  EXPECT_EQ(again.reference.seed, 12u);
  EXPECT_EQ(again.identity, first.identity);
}

TEST(SweepOptions, identity_lists_the_content_keys_in_shortest_decimals) {
  const SweepConfig c = parse({"--output", "elsewhere.h5", "--quiet"});
  ASSERT_EQ(c.identity.size(), 15u);
  EXPECT_EQ(c.identity[0], "grid.l = 0.5, 0.625, 0.75, 0.875, 1, 1.125, 1.25");
  EXPECT_EQ(c.identity[2], "grid.T = 2, 3, 4, 5, 6, 7, 8, 9, 10");
  EXPECT_EQ(c.identity[3].rfind("grid.pbar = 0.005, ", 0), 0u) << c.identity[3];
  EXPECT_EQ(c.identity[4], "grid.s = 1, 2, 3");
  EXPECT_EQ(c.identity[5], "model.C = 0.5");
  EXPECT_EQ(c.identity[6], "model.creep_law = standard_linear_solid");
  EXPECT_EQ(c.identity[7], "model.localization = periodic");  // the default
  EXPECT_EQ(c.identity[8], "time.times = 0, 0.5, 1, 2, 5");
  EXPECT_EQ(c.identity[9], "output.quantities = full");
  EXPECT_EQ(c.identity[10], "run.chunk = 4096");
  EXPECT_EQ(c.identity[11], "reference.method = none");
  EXPECT_EQ(c.identity[12], "reference.grid = 128");
  EXPECT_EQ(c.identity[13], "reference.sample = all");
  EXPECT_EQ(c.identity[14], "reference.seed = 1");
  // The paper's model leaves no line (maps made when it was the default resume).
  const SweepConfig paper = parse({"--model.localization", "paper"});
  ASSERT_EQ(paper.identity.size(), 14u);
  EXPECT_EQ(paper.identity[7], "time.times = 0, 0.5, 1, 2, 5");
  EXPECT_EQ(c.identity, parse({}).identity);  // where the map goes does not change what it holds
  // A map with BEM points names its solver, so that one made by another does not resume.
  const SweepConfig bem = parse({"--reference", "bem"});
  ASSERT_EQ(bem.identity.size(), 16u);
  EXPECT_EQ(bem.identity[15].rfind("reference.solver = 2 (quarter cell", 0), 0u) << bem.identity[15];
}

TEST(SweepOptions, identity_is_equal_for_equivalent_specs) {
  const SweepConfig by_function = parse({});
  const SweepConfig by_list = parse(
      {"--grid.l", "0.5, 0.625, 0.75, 0.875, 1, 1.125, 1.25",
       "--grid.T", "2 3 4 5 6 7 8 9 10", "--grid.s", "linspace(1, 3, 3)", "--model.C", "0.50",
       "--model.creep_law", "sls", "--time.times", "0.0,0.5,1,2,5.0"});
  EXPECT_EQ(by_list.identity, by_function.identity);
  EXPECT_NE(by_list.resolved_text, by_function.resolved_text);
  EXPECT_NE(parse({"--grid.T", "2, 5"}).identity, by_function.identity);
}

TEST(SweepOptions, identity_differences_name_each_differing_key) {
  const std::vector<std::string> existing = parse({"--grid.T", "2, 5, 10"}).identity;
  EXPECT_TRUE(identity_differences(existing, parse({"--grid.T", "2 5 10", "--output", "x.h5"}).identity).empty());
  const std::vector<std::string> differences =
      identity_differences(existing, parse({"--grid.T", "2, 5", "--chunk", "100"}).identity);
  ASSERT_EQ(differences.size(), 2u);
  EXPECT_EQ(differences[0], "grid.T: the existing map has 2, 5, 10; this run asks for 2, 5");
  EXPECT_EQ(differences[1], "run.chunk: the existing map has 4096; this run asks for 100");
}

TEST(SweepOptions, identity_differences_name_each_differing_reference_key) {
  const std::vector<std::string> existing =
      parse({"--reference", "bem", "--bem-grid", "32", "--reference.sample", "5"}).identity;
  EXPECT_TRUE(identity_differences(existing, parse({"--reference.method", "bem", "--reference.grid", "032",
                                                    "--reference.sample", "5", "--reference.seed", "1"})
                                                 .identity)
                  .empty());
  const std::vector<std::string> differences = identity_differences(
      existing, parse({"--bem-grid", "64", "--reference.sample", "all", "--reference.seed", "2"}).identity);
  ASSERT_EQ(differences.size(), 5u);
  EXPECT_EQ(differences[0], "reference.method: the existing map has bem; this run asks for none");
  EXPECT_EQ(differences[1], "reference.grid: the existing map has 32; this run asks for 64");
  EXPECT_EQ(differences[2], "reference.sample: the existing map has 5; this run asks for all");
  EXPECT_EQ(differences[3], "reference.seed: the existing map has 1; this run asks for 2");
  EXPECT_EQ(differences[4].rfind("reference.solver: the existing map has 2 (quarter cell", 0), 0u) << differences[4];
}

TEST(SweepOptions, identity_differences_report_keys_only_one_side_has) {
  const std::vector<std::string> differences =
      identity_differences({"grid.T = 2", "model.C = 0.5"}, {"grid.T = 2", "run.chunk = 8"});
  ASSERT_EQ(differences.size(), 2u);
  EXPECT_EQ(differences[0], "model.C: the existing map has 0.5; this run does not set it");
  EXPECT_EQ(differences[1], "run.chunk: the existing map does not record it; this run asks for 8");
}

TEST(SweepOptions, a_byte_order_mark_is_ignored_and_a_binary_file_refused_in_one_line) {
  const std::string bom = ::testing::TempDir() + "/bom.ini";
  std::ofstream(bom) << "\xEF\xBB\xBF[grid]\nT = 2, 3\n";
  EXPECT_EQ(parse({"--config", bom}).grid.axes[2].values, (std::vector<double>{2, 3}));
  const std::string binary = ::testing::TempDir() + "/binary.ini";
  std::ofstream(binary) << "[grid]\nT = 2\n\x7F" << "ELF\x02\x01\x01" << std::string(3, '\0') << "\x1B[31m\n";
  const std::string message = refusal({"--config", binary});
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 0) << message;
  EXPECT_NE(message.find("line 3: byte 0x7F is a control character"), std::string::npos) << message;
}

TEST(SweepOptions, minus_zero_is_stored_as_zero) {
  const SweepConfig c = parse({"--grid.dh", "-0, 0.1"});
  EXPECT_FALSE(std::signbit(c.grid.axes[1].values[0]));
}

TEST(SweepOptions, resume_and_overwrite_together_are_refused) {
  EXPECT_NE(refusal({"--resume", "--overwrite"}).find("give only one"), std::string::npos);
}

}  // namespace
