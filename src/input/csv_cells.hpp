#pragma once
/// @file
/// The cells of a line of text as spreadsheets and instruments export them: the separator a
/// line uses, cells split at it outside double quotes, and a cell's number with or without a
/// decimal comma. The measurement files of `punchsweep fit` and the height maps of
/// `punchsweep surface` read their cells with these, so that both read one layout alike.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace punchsweep::input {

/// A cell without the blanks and the quotes around it.
std::string trim_cell(std::string_view cell);

/// The cells of a line: split at `sep` outside double quotes (a spreadsheet quotes a cell
/// that holds the separator, and doubles a quote inside one: "a ""b"", c"), each trimmed.
std::vector<std::string> split_cells(std::string_view line, char sep);

/// The separator of a line: a semicolon or a tab where it has one, else a comma.
char separator_of(std::string_view line);

/// Whether a file separated by `sep` writes a decimal comma: with semicolons or tabs
/// between values (as spreadsheets in many locales write them) a comma is the decimal point.
inline bool decimal_comma_with(char sep) { return sep == ';' || sep == '\t'; }

/// A cell's number: a leading '+' allowed; with `decimal_comma` "4,52" is 4.52. Nothing for
/// a cell that is not wholly one finite number.
std::optional<double> cell_number(const std::string& written, bool decimal_comma);

}  // namespace punchsweep::input
