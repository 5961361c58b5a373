// shapesplines: the ShapeSplines filters from the command line.
//   shapesplines fit INPUT -o OUTPUT [options]   fit spline curves to polylines
//   shapesplines audit INPUT [CURVE] [options]   discrete shape, and a curve's audit
// Reads .vtp, legacy .vtk and .csv; writes .vtp or .csv. Run with --help.
#include "ArrayNames.h"
#include "LineCells.h"

#include "vtkCubicSplineFilter.h"
#include "vtkGeneralizedCubicSplineFilter.h"
#include "vtkQQRSplineFilter.h"
#include "vtkPolylineShapeAnalysis.h"
#include "vtkTensionQuinticSplineFilter.h"
#include "vtkVariableDegreeSplineFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unistd.h>
#include <vector>

namespace names = shapesplines::names;

namespace
{
const char* const Usage = R"(shapesplines: shape-preserving spline curves with curvature and torsion

Usage:
  shapesplines fit INPUT -o OUTPUT [options]
  shapesplines audit INPUT [CURVE] [-o OUTPUT] [--closed]
  shapesplines --help | --version

fit: one spline curve per polyline of INPUT, sampled with its exact Frenet frame,
curvature and signed torsion, audited against the shape of the data (Costantini & Manni (VDPS),
Definition 1). Prints a summary per line.
audit: the discrete shape of INPUT's polylines (curvature, torsion, collinear and
coplanar runs) and, given a CURVE fitted to them by `fit`, where it breaks that
shape. Lines pair in order; a CURVE that does not match INPUT (another number
of lines, of spans, or closure) is an error.

Files: INPUT and CURVE are .vtp, legacy .vtk or .csv; OUTPUT is .vtp or .csv.
OUTPUT is never INPUT. INPUT or CURVE - reads stdin: VTK XML if it starts with
<?xml or <VTKFile, legacy VTK if with # vtk DataFile, else CSV. -o - writes CSV
on stdout, and the summary goes to stderr (a .vtp is written to a file). A .vtp
is written with raw appended data compressed by LZ4 (fast; ParaView reads it).
CSV input: a row per point; # starts a comment, blank rows are skipped. A first
row whose first field is not a number is a header naming the columns: x, y, z,
the line ids and any others, which become point arrays (name_0, name_1, ... in
adjacent columns are the components of one array); names are compared without
case and may not repeat. The line ids are in the column --line-column names,
else in the one named line_id, line, lineid, id, cell, cell_id, track or
streamline (line_id before the others; two others are an error). The rows with
the same id form a polyline, in file order (they need not be consecutive), and
it keeps its id (cell array LineId); without line ids the file is one polyline.
Without a header a CSV has 3 columns (x,y,z) or 4 (x,y,z,line_id). Every row
has as many fields as the header (or the first row). A column taken for line
ids by its name or place that gives every row a line of its own is refused.
CSV dialect: UTF-8 (a byte order mark is skipped) or ASCII, LF or CRLF line
ends; the separator is a tab if the first row has one, else ';' if it has one,
else ','; a field may be in double quotes, and may then hold the separator and
#, with "" for a quote; blanks around a field are ignored; numbers have a
decimal point, not a comma.
CSV output: a row per sample, line_id (the input's, else the line's place)
then x,y,z then every point array: a CSV written by fit reads back whole.

Shape violations (Costantini & Manni (VDPS), Definition 1): fit counts them in its own audit of
each curve, the curve's cell array ShapeViolations: 16 samples a span whatever
the output's sampling, each knot seen from both of its spans, samples whose
curvature is within rounding of zero left out, spans straying from the data
counted. audit can only read the written samples: one frame per knot (the span
that starts there), the output's sampling, no rounding. So each count says
which it is ("fit's audit", "in the written samples"), and audit also prints
fit's count when CURVE holds it (.vtp). fit's counts more at knots: a C2
curve's torsion jumps there, and the side audit does not see can have the
wrong sign.

Options of fit:
  --family NAME          spline family (default cubic):
                           cubic     classical C2 cubic spline (the baseline)
                           gencubic  C2 generalized cubic, automatic tension
                           quintic   C3/C4 tensioned quintic, automatic tension
                           vdps      C3 variable degree spline, automatic degrees
                           qqr       C2 qqr B-spline-like curve through the points
                                     (or --mode approximate: points = control polygon)
  --end-condition NAME   cubic: not-a-knot (default), natural or clamped;
                         gencubic: polynomial (default) or natural;
                         vdps: polynomial (default), natural or clamped
  --kind NAME            gencubic: exponential (default), trigonometric,
                         variable-degree or polynomial
  --tension T            gencubic: starting tension (fixed with --fixed);
                         the degree for variable-degree (default 0)
  --max-tension T        gencubic: cap of the automatic tension (default 1000)
  --fixed                gencubic, quintic, vdps, qqr: Automatic off (fixed
                         tension, gamma, degrees or exponents)
  --continuity C         quintic: c4 (default) or c3
  --mode M               quintic: interpolate (default) or approximate;
                         qqr: interpolate (default), approximate or local
                         (the paper's local interpolation: curvature 3x off);
                         vdps: interpolate (default), approximate (the local
                         scheme), approximate-global or approximate-local
  --knots N              approximate: number of knots, at most half the points;
                         0 (default) chooses per line from the data
  --keep-parameters      approximate: keep the parameterization's parameters
                         (default: corrected towards the curve)
  --gamma G, --lambda L  quintic: fixed shape parameters (default 1, 1);
                         vdps: --lambda is the corner cutting tension (1)
  --degree K             vdps: starting (fixed with --fixed) degree (default 5)
  --max-degree K         vdps: cap of the automatic degrees (default 1000)
  --alpha A, --beta B    qqr: exponents (default 4, 4; automatic starts there)
  --max-alpha A          qqr: cap of the automatic exponents (default 200)
  --z Z                  qqr: local bias z at every knot instead of the paper's
  --parameterization P   chord (default), centripetal or uniform knots
  --closed               close every line of 3 or more distinct points
  --samples N            N samples per span between data points (default 10)
  --arc-length L         samples about L apart along the curve instead
  --vmtk-names           also write the frame as FrenetTangent/Normal/Binormal
  --data-tolerance E     shape tolerance epsilon_1 on the data (default 1e-6)
  --curve-tolerance E    shape tolerance epsilon_2 on the curve (default 1e-3)
Common options:
  -o, --output OUTPUT    output file (required for fit), - for CSV on stdout
  --line-column NAME     CSV INPUT: the column of line ids (see above)
  -q, --quiet            no summary and no progress bar
  -h, --help             this text
  --version              the version of shapesplines
Each option may be given once.

Exit status: 0 on success, 1 on bad usage, unreadable input, a CURVE that does
not match INPUT, or an output that cannot be written (checked before any work,
and again when written), 2 when the filter reported errors (lines skipped: see
the messages).
)";

const char* const Version = "shapesplines " SHAPESPLINES_VERSION "\n";

struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Extension(const std::string& path)
{
  return Lower(std::filesystem::path(path).extension().string());
}

/// Command-line arguments: positionals, and options with or without a value.
struct Arguments
{
  std::vector<std::string> Positional;
  std::map<std::string, std::string> Options;
  std::set<std::string> Used;

  bool Flag(const std::string& name)
  {
    this->Used.insert(name);
    return this->Options.count(name) > 0;
  }

  std::string Value(const std::string& name, const std::string& fallback)
  {
    this->Used.insert(name);
    const auto it = this->Options.find(name);
    return it == this->Options.end() ? fallback : it->second;
  }

  double Number(const std::string& name, double fallback, double lo, double hi)
  {
    const std::string text = this->Value(name, "");
    if (text.empty())
    {
      return fallback;
    }
    size_t end = 0;
    double value = std::numeric_limits<double>::quiet_NaN();
    try
    {
      value = std::stod(text, &end);
    }
    catch (const std::exception&)
    {
    }
    if (end != text.size() || !(value >= lo && value <= hi))
    {
      std::ostringstream message;
      message << "--" << name << " must be a number in [" << lo << ", " << hi << "], not '" << text
              << "'";
      throw UsageError(message.str());
    }
    return value;
  }

  /// Options nobody asked for are mistakes, not silently ignored.
  void RejectUnused() const
  {
    for (const auto& option : this->Options)
    {
      if (!this->Used.count(option.first))
      {
        throw UsageError("unknown option --" + option.first + " for this command or family");
      }
    }
  }
};

const std::set<std::string> ValueOptions = { "output", "family", "end-condition", "kind",
  "tension", "max-tension", "continuity", "mode", "knots", "gamma", "lambda", "degree",
  "max-degree", "alpha", "beta", "max-alpha", "z", "parameterization", "samples", "arc-length",
  "data-tolerance", "curve-tolerance", "line-column" };
const std::set<std::string> FlagOptions = { "closed", "vmtk-names", "fixed", "keep-parameters",
  "quiet", "help", "version" };

Arguments Parse(int argc, char* argv[])
{
  Arguments args;
  for (int i = 2; i < argc; ++i)
  {
    std::string word = argv[i];
    if (word == "-o")
    {
      word = "--output";
    }
    else if (word == "-q")
    {
      word = "--quiet";
    }
    else if (word == "-h")
    {
      word = "--help";
    }
    if (word.size() > 1 && word[0] == '-' && word[1] != '-')
    {
      throw UsageError("unknown option " + word);
    }
    if (word.rfind("--", 0) != 0 || word.size() == 2)
    {
      args.Positional.push_back(word);
      continue;
    }
    std::string name = word.substr(2);
    std::string value;
    const size_t equals = name.find('=');
    if (equals != std::string::npos)
    {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
    }
    if (!ValueOptions.count(name) && !FlagOptions.count(name))
    {
      throw UsageError("unknown option --" + name);
    }
    if (equals == std::string::npos && ValueOptions.count(name))
    {
      if (i + 1 >= argc)
      {
        throw UsageError("--" + name + " needs a value");
      }
      value = argv[++i];
    }
    // A repeated option is a mistake whichever one was meant: -o a -o b.
    const auto [previous, added] = args.Options.emplace(name, value);
    if (!added)
    {
      throw UsageError("--" + name + " is given twice" +
        (ValueOptions.count(name) ? " ('" + previous->second + "' and '" + value + "')" : "") +
        ": give each option once");
    }
  }
  return args;
}

// --------------------------------------------------------------------------- files

/// A VTK message without its origin: VTK's text reads
/// "Warning: In file, line N\nclass (address): message\n\n".
std::string MessageText(const char* text)
{
  std::string message = text;
  const size_t origin = message.find("): ");
  if (origin != std::string::npos)
  {
    message = message.substr(origin + 3);
  }
  message.erase(message.find_last_not_of("\n") + 1);
  return message;
}

/// The errors of a reader or writer and its pipeline, kept for one message of ours
/// instead of VTK's log lines.
struct FileErrors
{
  explicit FileErrors(vtkAlgorithm* algorithm)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
      auto* errors = static_cast<FileErrors*>(self);
      if (errors->First.empty())
      {
        errors->First = MessageText(static_cast<const char*>(text));
      }
    });
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  }

  vtkNew<vtkCallbackCommand> Callback;
  std::string First;
};

std::string Trim(const std::string& text)
{
  const size_t first = text.find_first_not_of(" \t\r");
  const size_t last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

std::string Join(const std::vector<std::string>& names)
{
  std::string text;
  for (const std::string& name : names)
  {
    text += (text.empty() ? "" : ", ") + name;
  }
  return text;
}

/// A CSV's separator, from its first row: a tab if the row has one outside double
/// quotes, else ';' if it has one, else ','.
char Separator(const std::string& row)
{
  bool quoted = false;
  bool semicolon = false;
  for (const char c : row)
  {
    if (c == '"')
    {
      quoted = !quoted;
    }
    else if (!quoted && c == '#')
    {
      break;
    }
    else if (!quoted && c == '\t')
    {
      return '\t';
    }
    semicolon = semicolon || (!quoted && c == ';');
  }
  return semicolon ? ';' : ',';
}

/// Splits a CSV row into fields, up to a # outside double quotes (a comment). A
/// double-quoted field may hold the separator and #, and "" for a quote; blanks
/// around a field are dropped.
std::vector<std::string> Fields(const std::string& row, char separator, const std::string& where)
{
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (size_t i = 0; i < row.size(); ++i)
  {
    const char c = row[i];
    if (quoted && c == '"' && i + 1 < row.size() && row[i + 1] == '"')
    {
      field += '"';
      ++i;
    }
    else if (c == '"')
    {
      quoted = !quoted;
    }
    else if (!quoted && c == separator)
    {
      fields.push_back(Trim(field));
      field.clear();
    }
    else if (!quoted && c == '#')
    {
      break;
    }
    else
    {
      field += c;
    }
  }
  if (quoted)
  {
    throw std::runtime_error(where + "a double quote is not closed (a field cannot span rows)");
  }
  fields.push_back(Trim(field));
  return fields;
}

bool ParseNumber(const std::string& text, double& value)
{
  size_t end = 0;
  try
  {
    value = std::stod(text, &end);
  }
  catch (const std::exception&)
  {
    return false;
  }
  return end == text.size();
}

/// What the columns of a CSV hold: x, y, z, line ids and point arrays (name or
/// name_0, name_1, ... for the components of one array).
struct CsvColumns
{
  std::vector<std::string> Names;            ///< x, y, z[, line_id] without a header
  bool Header = false;
  std::array<size_t, 3> Position = { 0, 1, 2 }; ///< of x, y and z
  int LineId = -1;                           ///< the column of line ids, -1 if none
  bool LineIdGuessed = false;                ///< by its name or place, not --line-column
  std::vector<std::pair<vtkSmartPointer<vtkDoubleArray>, size_t>> Arrays; ///< and first column
};

CsvColumns HeaderColumns(
  const std::vector<std::string>& names, const std::string& lineColumn, const std::string& where)
{
  CsvColumns columns;
  columns.Names = names;
  columns.Header = true;
  std::array<int, 3> axes = { -1, -1, -1 };
  std::vector<size_t> lineIdColumns;
  std::map<std::string, size_t> seen;
  for (size_t f = 0; f < names.size(); ++f)
  {
    const std::string name = Lower(names[f]);
    if (name.empty())
    {
      throw std::runtime_error(
        where + "column " + std::to_string(f + 1) + " of the header has no name");
    }
    const auto [previous, added] = seen.emplace(name, f);
    if (!added)
    {
      throw std::runtime_error(where + "the header names '" + names[f] + "' twice (columns " +
        std::to_string(previous->second + 1) + " and " + std::to_string(f + 1) +
        "; names are compared without case)");
    }
    if (name == "x" || name == "y" || name == "z")
    {
      axes[name[0] - 'x'] = static_cast<int>(f);
    }
    else if (lineColumn.empty()
        ? shapesplines::isLineIdName(name)
        : name == Lower(lineColumn))
    {
      lineIdColumns.push_back(f);
    }
  }
  if (std::count(axes.begin(), axes.end(), -1) > 0)
  {
    throw std::runtime_error(
      where + "the header must name the columns x, y and z; it names " + Join(names));
  }
  if (!lineColumn.empty() && lineIdColumns.empty())
  {
    throw std::runtime_error(where + "no column is named '" + lineColumn +
      "' (--line-column); the header names " + Join(names));
  }
  // line_id, the name fit writes, before the others: a curve's CSV always reads back.
  const auto canonical = std::find_if(lineIdColumns.begin(), lineIdColumns.end(),
    [&](size_t f) { return Lower(names[f]) == "line_id"; });
  if (canonical != lineIdColumns.end())
  {
    lineIdColumns = { *canonical };
  }
  if (lineIdColumns.size() > 1)
  {
    throw std::runtime_error(where + "the columns '" + names[lineIdColumns[0]] + "' and '" +
      names[lineIdColumns[1]] + "' both name line ids: choose one with --line-column");
  }
  std::copy(axes.begin(), axes.end(), columns.Position.begin());
  columns.LineId = lineIdColumns.empty() ? -1 : static_cast<int>(lineIdColumns[0]);
  columns.LineIdGuessed = lineColumn.empty();
  for (size_t f = 0; f < names.size(); ++f)
  {
    if (std::count(axes.begin(), axes.end(), static_cast<int>(f)) > 0 ||
      static_cast<int>(f) == columns.LineId)
    {
      continue;
    }
    // name_0, name_1, ... in adjacent columns are the components of one array.
    const size_t underscore = names[f].rfind('_');
    const std::string base = underscore == std::string::npos ? "" : names[f].substr(0, underscore);
    const std::string component =
      underscore == std::string::npos ? "" : names[f].substr(underscore + 1);
    if (!columns.Arrays.empty() && !base.empty())
    {
      auto& [array, start] = columns.Arrays.back();
      const int components = array->GetNumberOfComponents();
      if (base == array->GetName() && component == std::to_string(components) &&
        f == start + components)
      {
        array->SetNumberOfComponents(components + 1);
        continue;
      }
    }
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(component == "0" ? base.c_str() : names[f].c_str());
    columns.Arrays.emplace_back(array, f);
  }
  return columns;
}

/// Without a header a CSV holds x,y,z or x,y,z,line_id: anything else needs names.
CsvColumns HeaderlessColumns(size_t count, const std::string& lineColumn, const std::string& where)
{
  if (!lineColumn.empty())
  {
    throw std::runtime_error(where + "--line-column " + lineColumn +
      " needs a header row naming the columns, and this CSV has none");
  }
  if (count != 3 && count != 4)
  {
    throw std::runtime_error(where + "this row has " + std::to_string(count) +
      " fields, and without a header a CSV has 3 (x,y,z) or 4 (x,y,z,line_id): add a header "
      "row naming the columns, e.g. x,y,z,line_id,radius (names other than x, y, z and the "
      "line id become point arrays)");
  }
  CsvColumns columns;
  columns.Names = { "x", "y", "z" };
  if (count == 4)
  {
    columns.Names.emplace_back("line_id");
    columns.LineId = 3;
    columns.LineIdGuessed = true;
  }
  return columns;
}

/// A CSV row as text: UTF-16 refused, a UTF-8 byte order mark and a CR line end dropped.
void CleanRow(std::string& row, int number, const std::string& where)
{
  if (number == 1 && (row.rfind("\xFF\xFE", 0) == 0 || row.rfind("\xFE\xFF", 0) == 0))
  {
    throw std::runtime_error(where + "the text is UTF-16: save the CSV as UTF-8");
  }
  if (number == 1 && row.rfind("\xEF\xBB\xBF", 0) == 0)
  {
    row.erase(0, 3); // the UTF-8 byte order mark some editors write
  }
  if (!row.empty() && row.back() == '\r')
  {
    row.pop_back();
  }
}

/// The points of a CSV's rows so far, with each row's line id when a column holds them.
struct CsvRows
{
  CsvRows() { this->Points->SetDataTypeToDouble(); }

  vtkNew<vtkPoints> Points;
  vtkNew<vtkDoubleArray> LineIds;
};

/// Appends a data row: its point, its values of the point arrays and its line id.
void AppendCsvRow(const std::vector<std::string>& fields, char separator,
  const CsvColumns& columns, const std::string& where, CsvRows& rows)
{
  if (fields.size() != columns.Names.size())
  {
    throw std::runtime_error(where + "this row has " + std::to_string(fields.size()) +
      " fields, " + (columns.Header ? "the header names " : "the first row has ") +
      std::to_string(columns.Names.size()));
  }
  const auto numberAt = [&](size_t column) {
    double parsed;
    if (!ParseNumber(fields[column], parsed))
    {
      const bool decimalComma = separator != ',' && fields[column].find(',') != std::string::npos;
      throw std::runtime_error(where + "column " + std::to_string(column + 1) + " (" +
        columns.Names[column] + ") is not a number: '" + fields[column] + "'" +
        (decimalComma ? " (decimal commas are not read: write 1.5, not 1,5)" : ""));
    }
    return parsed;
  };
  const double xyz[3] = { numberAt(columns.Position[0]), numberAt(columns.Position[1]),
    numberAt(columns.Position[2]) };
  std::vector<double> tuple;
  for (const auto& [array, column] : columns.Arrays)
  {
    tuple.resize(array->GetNumberOfComponents());
    for (size_t c = 0; c < tuple.size(); ++c)
    {
      tuple[c] = numberAt(column + c);
    }
    array->InsertNextTuple(tuple.data());
  }
  if (columns.LineId >= 0)
  {
    const double id = numberAt(columns.LineId);
    if (!std::isfinite(id))
    {
      throw std::runtime_error(
        where + "line id " + fields[columns.LineId] + ": line ids must be finite numbers");
    }
    rows.LineIds->InsertNextValue(id);
  }
  rows.Points->InsertNextPoint(xyz);
}

/// A column taken for line ids by its name or place that gives every row its own
/// line numbers points or times, not lines: nothing could be fitted.
void CheckGuessedLineIds(
  const CsvColumns& columns, vtkIdType rows, vtkIdType lines, const std::string& name)
{
  if (!columns.LineIdGuessed || rows <= 1 || lines != rows)
  {
    return;
  }
  const std::string column = columns.Names[columns.LineId];
  throw std::runtime_error(name + ": " +
    (columns.Header ? "the column '" + column + "'" : "column 4 of a CSV without a header") +
    ", read as line ids, gives each of its " + std::to_string(rows) +
    " rows a line of its own: " +
    (columns.Header ? "if it numbers points, not lines, rename it (other names become point "
                      "arrays), or name the line id column with --line-column"
                    : "if it is not a line id, add a header row naming the columns, e.g. "
                      "x,y,z,time"));
}

/// The poly data of a CSV's rows: a line per line id, the ids as cell array LineId,
/// the other columns as point arrays.
vtkSmartPointer<vtkPolyData> CsvPolyData(
  const CsvColumns& columns, const CsvRows& rows, const std::string& name)
{
  // The rows of a line need not be consecutive (tracks interleaved by time):
  // grouped as the filters' Connect Points groups points.
  const vtkIdType rowCount = rows.Points->GetNumberOfPoints();
  vtkDataArray* idOfRow = columns.LineId >= 0 ? rows.LineIds.Get() : nullptr;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> lineIds;
  lineIds->SetName(names::LineId);
  for (const auto& line : shapesplines::connectedPoints(rowCount, idOfRow))
  {
    lines->InsertNextCell(static_cast<vtkIdType>(line.PointIds.size()), line.PointIds.data());
    if (idOfRow)
    {
      lineIds->InsertNextValue(idOfRow->GetComponent(line.PointIds[0], 0));
    }
  }
  CheckGuessedLineIds(columns, rowCount, lines->GetNumberOfCells(), name);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(rows.Points);
  data->SetLines(lines);
  if (columns.LineId >= 0)
  {
    data->GetCellData()->AddArray(lineIds);
  }
  for (const auto& column : columns.Arrays)
  {
    data->GetPointData()->AddArray(column.first);
  }
  return data;
}

vtkSmartPointer<vtkPolyData> ReadCsv(
  std::istream& file, const std::string& name, const std::string& lineColumn)
{
  CsvColumns columns;
  CsvRows rows;
  char separator = ',';
  bool first = true; ///< no row with fields read yet: the next is the header or first row
  std::string row;
  for (int number = 1; std::getline(file, row); ++number)
  {
    const std::string where = name + ":" + std::to_string(number) + ": ";
    CleanRow(row, number, where);
    if (first)
    {
      separator = Separator(row);
    }
    const std::vector<std::string> fields = Fields(row, separator, where);
    if (fields.size() == 1 && fields[0].empty())
    {
      continue;
    }
    if (first)
    {
      first = false;
      double value;
      if (!ParseNumber(fields[0], value))
      {
        columns = HeaderColumns(fields, lineColumn, where);
        continue;
      }
      columns = HeaderlessColumns(fields.size(), lineColumn, where);
    }
    AppendCsvRow(fields, separator, columns, where, rows);
  }
  return CsvPolyData(columns, rows, name);
}

/// The format of what stdin holds: VTK XML or legacy VTK by their first words, else CSV.
std::string StandardInputFormat(const std::string& content)
{
  const size_t bom = content.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  const size_t start = std::min(content.find_first_not_of(" \t\r\n", bom), content.size());
  const auto startsWith = [&](const char* word) {
    return content.compare(start, std::strlen(word), word) == 0;
  };
  return startsWith("<?xml") || startsWith("<VTKFile") ? ".vtp"
    : startsWith("# vtk DataFile")                     ? ".vtk"
                                                       : ".csv";
}

/// How messages name an INPUT or CURVE: "-" is stdin.
std::string InputName(const std::string& path)
{
  return path == "-" ? "stdin" : path;
}

/// Reads a .vtp, legacy .vtk or .csv file, or stdin for "-" (see StandardInputFormat);
/// lineColumn names a CSV's line id column.
vtkSmartPointer<vtkPolyData> Read(const std::string& path, const std::string& lineColumn = "")
{
  const bool standardInput = path == "-";
  const std::string name = InputName(path);
  std::string content;
  if (standardInput)
  {
    if (isatty(STDIN_FILENO))
    {
      throw UsageError("- reads stdin, which is a terminal: pipe the data in");
    }
    content.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  }
  else if (!std::filesystem::is_regular_file(path))
  {
    throw std::runtime_error("no such file: " + path);
  }
  const std::string extension = standardInput ? StandardInputFormat(content) : Extension(path);
  if (!lineColumn.empty() && extension != ".csv")
  {
    throw UsageError("--line-column names a column of a CSV INPUT, and " + name + " is not one");
  }
  vtkSmartPointer<vtkPolyData> data;
  if (extension == ".csv" && standardInput)
  {
    std::istringstream stream(content);
    data = ReadCsv(stream, name, lineColumn);
  }
  else if (extension == ".csv")
  {
    std::ifstream file(path);
    if (!file)
    {
      throw std::runtime_error("cannot open " + path);
    }
    data = ReadCsv(file, path, lineColumn);
  }
  else if (extension == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    if (standardInput)
    {
      reader->ReadFromInputStringOn();
      reader->SetInputString(content);
    }
    else
    {
      reader->SetFileName(path.c_str());
    }
    FileErrors errors(reader);
    reader->Update();
    if (!errors.First.empty())
    {
      throw std::runtime_error("cannot read " + name + ": " + errors.First);
    }
    data = reader->GetOutput();
  }
  else if (extension == ".vtk")
  {
    vtkNew<vtkPolyDataReader> reader;
    if (standardInput)
    {
      reader->ReadFromInputStringOn();
      reader->SetInputString(content.data(), static_cast<int>(content.size()));
    }
    else
    {
      reader->SetFileName(path.c_str());
    }
    FileErrors errors(reader);
    if (!reader->IsFilePolyData())
    {
      throw std::runtime_error(name + " is not a legacy VTK poly data file");
    }
    reader->Update();
    if (!errors.First.empty())
    {
      throw std::runtime_error("cannot read " + name + ": " + errors.First);
    }
    data = reader->GetOutput();
  }
  else
  {
    throw std::runtime_error("cannot read '" + extension + "' files (" + path +
      "): use .vtp, .vtk or .csv");
  }
  if (!data || data->GetNumberOfPoints() == 0)
  {
    throw std::runtime_error("no points read from " + name);
  }
  return data;
}

/// Why the last system call failed, in the system's words.
std::string SystemError()
{
  return errno != 0 ? std::strerror(errno) : "unknown error";
}

/// Refuses an output that cannot be written before any work is done, so that a
/// long fit does not end in "cannot write". A file made to find out is removed.
void CheckWritable(const std::string& path)
{
  if (path == "-")
  {
    return; // stdout: a write error is found when written
  }
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
  {
    throw std::runtime_error("cannot write " + path + ": it is a directory");
  }
  const std::string extension = Extension(path);
  if (extension != ".csv" && extension != ".vtp")
  {
    throw UsageError("cannot write '" + extension + "' files (" + path + "): use .vtp or .csv");
  }
  const bool existed = std::filesystem::exists(path, error);
  errno = 0;
  std::ofstream probe(path, std::ios::app);
  if (!probe)
  {
    throw std::runtime_error("cannot write " + path + ": " + SystemError());
  }
  probe.close();
  if (!existed)
  {
    std::filesystem::remove(path, error);
  }
}

/// A name as a CSV field: double-quoted when it holds a separator, a quote or #.
std::string CsvField(const std::string& name)
{
  if (name.find_first_of(",;\t\"#") == std::string::npos)
  {
    return name;
  }
  std::string quoted = "\"";
  for (const char c : name)
  {
    quoted += c == '"' ? "\"\"" : std::string(1, c);
  }
  return quoted + "\"";
}

/// A line's id: its LineId (from the input), else its place among the lines.
double LineIdOf(vtkPolyData* data, vtkIdType line)
{
  vtkDataArray* ids = data->GetCellData()->GetArray(names::LineId);
  // Cell ids count the vertices first.
  return ids ? ids->GetComponent(data->GetNumberOfVerts() + line, 0) : static_cast<double>(line);
}

void WriteCsv(vtkPolyData* data, std::ostream& file)
{
  file.precision(17);
  std::vector<vtkDataArray*> arrays;
  file << "line_id,x,y,z";
  vtkPointData* pd = data->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || !array->GetName())
    {
      continue;
    }
    arrays.push_back(array);
    const int components = array->GetNumberOfComponents();
    for (int c = 0; c < components; ++c)
    {
      file << ',' << CsvField(array->GetName() + (components > 1 ? "_" + std::to_string(c) : ""));
    }
  }
  file << '\n';
  auto it = vtk::TakeSmartPointer(data->GetLines()->NewIterator());
  vtkIdType line = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++line)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    // A closed line's cell repeats its first sample; a CSV row per sample is enough.
    if (n > 2 && ids[0] == ids[n - 1])
    {
      --n;
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      double p[3];
      data->GetPoint(ids[k], p);
      file << LineIdOf(data, line) << ',' << p[0] << ',' << p[1] << ',' << p[2];
      for (vtkDataArray* array : arrays)
      {
        for (int c = 0; c < array->GetNumberOfComponents(); ++c)
        {
          file << ',' << array->GetComponent(ids[k], c);
        }
      }
      file << '\n';
    }
  }
}

/// Writes a .vtp or .csv file, or CSV on stdout for "-".
void Write(vtkPolyData* data, const std::string& path)
{
  if (path == "-")
  {
    errno = 0;
    WriteCsv(data, std::cout);
    std::cout.flush();
    if (!std::cout)
    {
      throw std::runtime_error("cannot write stdout: " + SystemError());
    }
    return;
  }
  if (Extension(path) == ".csv")
  {
    errno = 0;
    std::ofstream file(path);
    if (!file)
    {
      throw std::runtime_error("cannot write " + path + ": " + SystemError());
    }
    WriteCsv(data, file);
    // The last rows reach the disk only when the file is closed.
    file.close();
    if (!file)
    {
      throw std::runtime_error("cannot write " + path + ": " + SystemError());
    }
    return;
  }
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  // Raw appended data, LZ4: a 1e6-sample curve writes in 0.16 s and 121 MB,
  // where VTK's default (base64, zlib) takes 4.9 s (7.7x the fit) and 129 MB;
  // ParaView and VTK 8.2 or later read it.
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToLZ4();
  // Its messages would say in VTK's words what ours says.
  FileErrors errors(writer);
  errno = 0;
  writer->Write();
  if (writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    throw std::runtime_error("cannot write " + path + ": " + SystemError());
  }
}

/// The output must not be one of the inputs.
void CheckNotAnInput(const std::string& output, const std::vector<std::string>& inputs)
{
  if (output == "-")
  {
    return; // stdout
  }
  for (const std::string& input : inputs)
  {
    std::error_code error;
    if (output == input || std::filesystem::equivalent(output, input, error))
    {
      throw UsageError("the output " + output + " is an input file: refusing to overwrite it");
    }
  }
}

// --------------------------------------------------------------------------- messages

/// VTK's errors and warnings from the filters, counted, printed on stderr.
struct MessageCounter
{
  explicit MessageCounter(std::initializer_list<vtkObject*> objects)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long event, void* self, void* text) {
      auto* counter = static_cast<MessageCounter*>(self);
      const bool error = event == vtkCommand::ErrorEvent;
      (error ? counter->Errors : counter->Warnings)++;
      std::cerr << (error ? "error: " : "warning: ") << MessageText(static_cast<const char*>(text))
                << '\n';
    });
    for (vtkObject* object : objects)
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
      object->AddObserver(vtkCommand::WarningEvent, this->Callback);
    }
  }

  vtkNew<vtkCallbackCommand> Callback;
  int Errors = 0;
  int Warnings = 0;
};

/// A progress bar on stderr when it is a terminal.
void ShowProgress(vtkAlgorithm* algorithm)
{
  if (!isatty(STDERR_FILENO))
  {
    return;
  }
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback([](vtkObject*, unsigned long, void*, void* amount) {
    const double done = *static_cast<double*>(amount);
    const int width = 40;
    const int filled = static_cast<int>(done * width);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] "
              << static_cast<int>(100 * done) << "%" << (done >= 1.0 ? "\n" : "") << std::flush;
  });
  algorithm->AddObserver(vtkCommand::ProgressEvent, progress);
}

/// How the summaries name a line: by its id (see LineIdOf), "line 5".
std::string LineName(vtkPolyData* data, vtkIdType line)
{
  std::ostringstream text;
  text.precision(17);
  text << "line " << LineIdOf(data, line);
  return text.str();
}

double CellValue(vtkPolyData* data, const char* name, vtkIdType cell)
{
  vtkDataArray* array = data->GetCellData()->GetArray(name);
  return array ? array->GetComponent(cell, 0) : std::numeric_limits<double>::quiet_NaN();
}

/// "[min, max]" of the values at the ids the data define (all when defined is empty), or
/// "undefined": the data's range, never widened to 0.
std::string RangeText(vtkDataArray* array, const vtkIdType* ids, vtkIdType n,
  const std::function<bool(vtkIdType)>& defined = {})
{
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (vtkIdType k = 0; k < n; ++k)
  {
    if (!defined || defined(ids[k]))
    {
      lo = std::min(lo, array->GetComponent(ids[k], 0));
      hi = std::max(hi, array->GetComponent(ids[k], 0));
    }
  }
  if (!(lo <= hi))
  {
    return "undefined";
  }
  std::ostringstream text;
  text << "[" << lo << ", " << hi << "]";
  return text.str();
}

/// One line per output line: samples, length, curvature and torsion ranges, violations.
void Summarize(vtkPolyData* curve, std::ostream& summary)
{
  vtkDataArray* curvature = curve->GetPointData()->GetArray(names::Curvature);
  vtkDataArray* torsion = curve->GetPointData()->GetArray(names::Torsion);
  auto it = vtk::TakeSmartPointer(curve->GetLines()->NewIterator());
  vtkIdType line = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++line)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    double maxCurvature = 0.0;
    for (vtkIdType k = 0; k < n; ++k)
    {
      maxCurvature = std::max(maxCurvature, curvature->GetComponent(ids[k], 0));
    }
    summary << LineName(curve, line) << ": " << n << " samples, length "
            << CellValue(curve, names::Length, line) << ", max curvature " << maxCurvature
            << ", torsion " << RangeText(torsion, ids, n) << ", shape violations "
            << CellValue(curve, names::ShapeViolations, line) << " (fit's audit)\n";
  }
}

const char* const OutOfRange = "a point id out of range";

/// Why a data line cannot be audited, or "": a point id out of range (checked
/// first: the others read the points), a point not finite, fewer than two
/// distinct points (no span).
std::string DataProblem(vtkPolyData* data, const vtkIdType* ids, vtkIdType n)
{
  if (std::any_of(
        ids, ids + n, [&](vtkIdType id) { return id < 0 || id >= data->GetNumberOfPoints(); }))
  {
    return OutOfRange;
  }
  double first[3] = { 0, 0, 0 };
  if (n > 0)
  {
    data->GetPoint(ids[0], first);
  }
  bool distinct = false;
  for (vtkIdType k = 0; k < n; ++k)
  {
    double p[3];
    data->GetPoint(ids[k], p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return "a point is not finite";
    }
    distinct = distinct || p[0] != first[0] || p[1] != first[1] || p[2] != first[2];
  }
  return distinct ? "" : "fewer than two distinct points";
}

// --------------------------------------------------------------------------- commands

/// The value of the choice option --option, fallback when not given; a name not among
/// choices is a usage error listing them, and saying for which family when another
/// family's list differs.
int Choice(Arguments& args, const std::string& option, const std::string& fallback,
  const std::vector<std::pair<std::string, int>>& choices, const std::string& family = "")
{
  const std::string value = args.Value(option, fallback);
  const auto chosen = std::find_if(
    choices.begin(), choices.end(), [&](const auto& choice) { return choice.first == value; });
  if (chosen != choices.end())
  {
    return chosen->second;
  }
  std::string names;
  for (size_t i = 0; i < choices.size(); ++i)
  {
    names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i].first;
  }
  throw UsageError(
    "--" + option + " must be " + names + (family.empty() ? "" : " for " + family));
}

/// The option --name's value in [lo, hi], current when not given; a whole
/// number for an integer property.
template <class T>
T OptionValue(Arguments& args, const std::string& name, T current, T lo, T hi)
{
  const double value = args.Number(name, current, lo, hi);
  if (std::is_integral<T>::value && value != std::floor(value))
  {
    throw UsageError("--" + name + " must be a whole number, not '" + args.Value(name, "") + "'");
  }
  return static_cast<T>(value);
}

/// Sets a filter's Property from the option --name when given: its default
/// and the range accepted are the filter's own (its vtkSetClampMacro bounds),
/// so the command line cannot drift from the filters.
#define SET_FROM_OPTION(args, filter, name, Property)                                              \
  (filter)->Set##Property(OptionValue((args), (name), (filter)->Get##Property(),                   \
    (filter)->Get##Property##MinValue(), (filter)->Get##Property##MaxValue()))

// Each family's filter, configured from its options; the options are read in a fixed
// order, so that of two bad options the same one is reported.

vtkSmartPointer<vtkShapeSplineFilter> CubicFilter(Arguments& args)
{
  auto filter = vtkSmartPointer<vtkCubicSplineFilter>::New();
  filter->SetEndCondition(Choice(args, "end-condition", "not-a-knot",
    { { "natural", vtkCubicSplineFilter::NATURAL },
      { "not-a-knot", vtkCubicSplineFilter::NOT_A_KNOT },
      { "clamped", vtkCubicSplineFilter::CLAMPED } }));
  return filter;
}

vtkSmartPointer<vtkShapeSplineFilter> GeneralizedCubicFilter(Arguments& args)
{
  auto filter = vtkSmartPointer<vtkGeneralizedCubicSplineFilter>::New();
  filter->SetSpaceKind(Choice(args, "kind", "exponential",
    { { "polynomial", vtkGeneralizedCubicSplineFilter::POLYNOMIAL },
      { "exponential", vtkGeneralizedCubicSplineFilter::EXPONENTIAL },
      { "trigonometric", vtkGeneralizedCubicSplineFilter::TRIGONOMETRIC },
      { "variable-degree", vtkGeneralizedCubicSplineFilter::VARIABLE_DEGREE } }));
  filter->SetAutomatic(!args.Flag("fixed"));
  SET_FROM_OPTION(args, filter, "tension", Tension);
  SET_FROM_OPTION(args, filter, "max-tension", MaxTension);
  filter->SetEndCondition(Choice(args, "end-condition", "polynomial",
    { { "polynomial", vtkGeneralizedCubicSplineFilter::POLYNOMIAL_ENDS },
      { "natural", vtkGeneralizedCubicSplineFilter::NATURAL_ENDS } },
    "gencubic"));
  return filter;
}

vtkSmartPointer<vtkShapeSplineFilter> TensionQuinticFilter(Arguments& args)
{
  auto filter = vtkSmartPointer<vtkTensionQuinticSplineFilter>::New();
  filter->SetContinuity(Choice(args, "continuity", "c4",
    { { "c3", vtkTensionQuinticSplineFilter::C3 }, { "c4", vtkTensionQuinticSplineFilter::C4 } }));
  filter->SetMode(Choice(args, "mode", "interpolate",
    { { "interpolate", vtkTensionQuinticSplineFilter::INTERPOLATE },
      { "approximate", vtkTensionQuinticSplineFilter::APPROXIMATE } }));
  SET_FROM_OPTION(args, filter, "knots", NumberOfKnots);
  filter->SetAutomatic(!args.Flag("fixed"));
  SET_FROM_OPTION(args, filter, "gamma", Gamma);
  SET_FROM_OPTION(args, filter, "lambda", Lambda);
  return filter;
}

vtkSmartPointer<vtkShapeSplineFilter> VariableDegreeFilter(Arguments& args)
{
  auto filter = vtkSmartPointer<vtkVariableDegreeSplineFilter>::New();
  filter->SetMode(Choice(args, "mode", "interpolate",
    { { "interpolate", vtkVariableDegreeSplineFilter::INTERPOLATE },
      { "approximate", vtkVariableDegreeSplineFilter::APPROXIMATE_LOCAL },
      { "approximate-global", vtkVariableDegreeSplineFilter::APPROXIMATE_GLOBAL },
      { "approximate-local", vtkVariableDegreeSplineFilter::APPROXIMATE_LOCAL } }));
  filter->SetEndCondition(Choice(args, "end-condition", "polynomial",
    { { "polynomial", vtkVariableDegreeSplineFilter::POLYNOMIAL },
      { "natural", vtkVariableDegreeSplineFilter::NATURAL },
      { "clamped", vtkVariableDegreeSplineFilter::CLAMPED } },
    "vdps"));
  SET_FROM_OPTION(args, filter, "knots", NumberOfKnots);
  filter->SetAutomatic(!args.Flag("fixed"));
  SET_FROM_OPTION(args, filter, "degree", Degree);
  SET_FROM_OPTION(args, filter, "max-degree", MaxDegree);
  SET_FROM_OPTION(args, filter, "lambda", Lambda);
  return filter;
}

vtkSmartPointer<vtkShapeSplineFilter> QQRFilter(Arguments& args)
{
  auto filter = vtkSmartPointer<vtkQQRSplineFilter>::New();
  filter->SetMode(Choice(args, "mode", "interpolate",
    { { "interpolate", vtkQQRSplineFilter::INTERPOLATE },
      { "approximate", vtkQQRSplineFilter::APPROXIMATE },
      { "local", vtkQQRSplineFilter::LOCAL_INTERPOLATION } },
    "qqr"));
  filter->SetAutomatic(!args.Flag("fixed"));
  SET_FROM_OPTION(args, filter, "alpha", Alpha);
  SET_FROM_OPTION(args, filter, "beta", Beta);
  SET_FROM_OPTION(args, filter, "max-alpha", MaxAlpha);
  if (args.Flag("z"))
  {
    filter->SetLocalParameters(vtkQQRSplineFilter::CUSTOM);
    SET_FROM_OPTION(args, filter, "z", Z);
  }
  return filter;
}

/// The spline families by their --family names.
using FamilyFactory = vtkSmartPointer<vtkShapeSplineFilter> (*)(Arguments&);
const std::map<std::string, FamilyFactory> Families = { { "cubic", CubicFilter },
  { "gencubic", GeneralizedCubicFilter }, { "quintic", TensionQuinticFilter },
  { "vdps", VariableDegreeFilter }, { "qqr", QQRFilter } };

int Fit(Arguments& args)
{
  if (args.Positional.size() != 1)
  {
    throw UsageError("fit takes one INPUT file");
  }
  const std::string input = args.Positional[0];
  const std::string output = args.Value("output", "");
  if (output.empty())
  {
    throw UsageError("fit needs -o OUTPUT");
  }
  CheckNotAnInput(output, { input });
  const std::string familyName = args.Value("family", "cubic");
  if (!Families.count(familyName))
  {
    throw UsageError("unknown --family " + familyName);
  }
  vtkSmartPointer<vtkShapeSplineFilter> filter = Families.at(familyName)(args);

  filter->SetParameterization(Choice(args, "parameterization", "chord",
    { { "chord", vtkShapeSplineFilter::CHORD_LENGTH },
      { "centripetal", vtkShapeSplineFilter::CENTRIPETAL },
      { "uniform", vtkShapeSplineFilter::UNIFORM } }));
  filter->SetCorrectParameters(!args.Flag("keep-parameters"));
  filter->SetClosed(args.Flag("closed"));
  filter->SetVMTKArrayNames(args.Flag("vmtk-names"));
  SET_FROM_OPTION(args, filter, "data-tolerance", DataShapeTolerance);
  SET_FROM_OPTION(args, filter, "curve-tolerance", CurveShapeTolerance);
  const bool byLength = !args.Value("arc-length", "").empty();
  if (byLength && !args.Value("samples", "").empty())
  {
    throw UsageError("give --samples or --arc-length, not both");
  }
  if (byLength)
  {
    filter->SetSamplingModeToArcLength();
    filter->SetSampleLength(args.Number("arc-length", 1.0, 1e-300, 1e300));
    if (!(filter->GetSampleLength() > 0.0))
    {
      throw UsageError("--arc-length must be positive");
    }
  }
  else
  {
    SET_FROM_OPTION(args, filter, "samples", NumberOfSubdivisions);
  }
  const std::string lineColumn = args.Value("line-column", "");
  const bool quiet = args.Flag("quiet");
  args.RejectUnused();
  CheckWritable(output);

  vtkSmartPointer<vtkPolyData> data = Read(input, lineColumn);
  if (data->GetNumberOfLines() == 0)
  {
    throw std::runtime_error(InputName(input) + " has no lines (polyline cells) to fit");
  }
  MessageCounter messages({ filter });
  if (!quiet)
  {
    ShowProgress(filter);
  }
  filter->SetInputData(data);
  filter->Update();
  vtkPolyData* curve = filter->GetOutput();
  Write(curve, output);
  if (!quiet)
  {
    // With the curve on stdout, the summary goes to stderr.
    std::ostream& summary = output == "-" ? std::cerr : std::cout;
    Summarize(curve, summary);
    summary << "wrote " << (output == "-" ? "stdout" : output) << " ("
            << curve->GetNumberOfLines() << " lines, " << curve->GetNumberOfPoints()
            << " samples)\n";
  }
  return messages.Errors > 0 ? 2 : 0;
}

/// Reads CURVE for audit: a curve written by fit, with a line per line of INPUT's data.
vtkSmartPointer<vtkPolyData> ReadFittedCurve(
  const std::string& path, const std::string& input, vtkPolyData* data)
{
  vtkSmartPointer<vtkPolyData> curve = Read(path);
  for (const char* name :
    { names::SpanIndex, names::Tangent, names::Binormal, names::Curvature, names::Torsion })
  {
    if (!curve->GetPointData()->GetArray(name))
    {
      throw std::runtime_error(InputName(path) + " has no point array " + name +
        ": CURVE must be a curve written by 'shapesplines fit' (or a Shape Splines filter)");
    }
  }
  // Lines are paired in order: with a line more or less every pair is wrong.
  if (curve->GetNumberOfLines() != data->GetNumberOfLines())
  {
    std::ostringstream message;
    message << "CURVE " << InputName(path) << " does not match INPUT " << InputName(input)
            << ": lines " << curve->GetNumberOfLines() << " in CURVE, "
            << data->GetNumberOfLines() << " in INPUT (audit a curve with the data it was "
            << "fitted to; a fit that skipped lines wrote fewer)";
    throw std::runtime_error(message.str());
  }
  return curve;
}

/// The analysis' point arrays of the data's discrete shape, summarized line by line.
struct DiscreteShape
{
  explicit DiscreteShape(vtkPolyData* result)
    : Curvature(result->GetPointData()->GetArray(names::DiscreteCurvature))
    , Torsion(result->GetPointData()->GetArray(names::DiscreteTorsion))
    , Collinear(result->GetPointData()->GetArray(names::Collinear))
    , Coplanar(result->GetPointData()->GetArray(names::Coplanar))
  {
  }

  void Summarize(const vtkIdType* ids, vtkIdType n, std::ostream& summary) const
  {
    // The segments at an open line's ends have no discrete torsion: 0 there, and
    // not coplanar; a coplanar segment's 0 is the data's.
    const auto definedTorsion = [&](vtkIdType id) {
      return this->Torsion->GetComponent(id, 0) != 0.0 ||
        this->Coplanar->GetComponent(id, 0) != 0.0;
    };
    double maxCurvature = 0.0;
    int collinearCount = 0;
    int coplanarCount = 0;
    for (vtkIdType k = 0; k < n; ++k)
    {
      maxCurvature = std::max(maxCurvature, this->Curvature->GetComponent(ids[k], 0));
      collinearCount += this->Collinear->GetComponent(ids[k], 0) != 0.0;
      coplanarCount += this->Coplanar->GetComponent(ids[k], 0) != 0.0;
    }
    summary << n << " points, max discrete curvature " << maxCurvature << ", discrete torsion "
            << RangeText(this->Torsion, ids, n, definedTorsion) << ", " << collinearCount
            << " collinear points, " << coplanarCount << " coplanar segments";
  }

  vtkDataArray* Curvature;
  vtkDataArray* Torsion;
  vtkDataArray* Collinear;
  vtkDataArray* Coplanar;
};

/// An audited curve's counts in the written samples, per criterion, and fit's count.
void SummarizeCurveAudit(
  vtkPolyData* result, vtkPolyData* curve, vtkIdType line, std::ostream& summary)
{
  const auto& criterionCount = names::CriterionViolations;
  summary << "; curve: " << CellValue(result, names::ShapeViolations, line)
          << " shape violations in the written samples (collinearity "
          << CellValue(result, criterionCount[0], line) << ", convexity "
          << CellValue(result, criterionCount[1], line) << "+"
          << CellValue(result, criterionCount[2], line) << ", coplanarity "
          << CellValue(result, criterionCount[3], line) << ", torsion sign "
          << CellValue(result, criterionCount[4], line) << "+"
          << CellValue(result, criterionCount[5], line) << ")";
  // A .vtp written by fit carries fit's count: see "Shape violations" in --help.
  if (curve->GetCellData()->GetArray(names::ShapeViolations))
  {
    summary << "; fit's audit: " << CellValue(curve, names::ShapeViolations, line);
  }
}

/// The lines whose curve audit could not check though their data are fine.
struct UnauditedCurves
{
  std::vector<std::string> Unmatched;      ///< spans or closure differ from the data's
  std::vector<std::string> Approximations; ///< knots that are not the data points
};

/// A line per line of the analysis' output: the data's discrete shape and, with a
/// CURVE, its audit or why it was not audited.
UnauditedCurves SummarizeAudit(vtkPolyData* result, vtkPolyData* curve, std::ostream& summary)
{
  const DiscreteShape shape(result);
  UnauditedCurves unaudited;
  auto it = vtk::TakeSmartPointer(result->GetLines()->NewIterator());
  vtkIdType line = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++line)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    const std::string problem = DataProblem(result, ids, n);
    summary << LineName(result, line) << ": ";
    if (problem == OutOfRange)
    {
      summary << "skipped (" << problem << ")\n";
      continue;
    }
    shape.Summarize(ids, n, summary);
    if (curve && CellValue(result, names::ShapeViolations, line) >= 0)
    {
      SummarizeCurveAudit(result, curve, line, summary);
    }
    else if (curve)
    {
      // Not audited (-1, or no counts at all): the data's doing, else the curve's. An
      // approximation's knots are not the data points (its NoiseLevel is the distance).
      const bool approximation = CellValue(curve, names::NoiseLevel, line) > 0.0;
      const std::string why = !result->GetCellData()->GetArray(names::ShapeViolations)
        ? "INPUT has cells other than lines: no counts per line"
        : !problem.empty() ? problem
        : approximation    ? "it approximates the data: its knots are not the data points"
                           : "it does not match the data";
      summary << "; curve: not audited (" << why << ")";
      if (problem.empty())
      {
        auto& lines = approximation ? unaudited.Approximations : unaudited.Unmatched;
        lines.push_back(LineName(result, line));
      }
    }
    summary << "\n";
  }
  return unaudited;
}

/// A curve audit could not check is an error: it was not fitted to these data, or
/// it approximates them (fit audits that against its reference polygon).
void CheckAudited(
  const UnauditedCurves& unaudited, const std::string& curvePath, const std::string& input)
{
  if (!unaudited.Unmatched.empty())
  {
    throw std::runtime_error("CURVE " + InputName(curvePath) + " does not match INPUT " +
      InputName(input) + " (" + Join(unaudited.Unmatched) +
      ": the curve's spans or closure differ from the data's, see the warnings): audit a curve "
      "with the data it was fitted to, and the same --closed (a curve that approximates the "
      "data is audited by fit alone)");
  }
  if (!unaudited.Approximations.empty())
  {
    throw std::runtime_error("CURVE " + InputName(curvePath) + " approximates INPUT " +
      InputName(input) + " (" + Join(unaudited.Approximations) +
      "): audit checks a curve through the data points; fit audited the approximation against "
      "its reference polygon (ShapeViolations in CURVE, printed by fit)");
  }
}

int Audit(Arguments& args)
{
  if (args.Positional.empty() || args.Positional.size() > 2)
  {
    throw UsageError("audit takes INPUT and optionally CURVE");
  }
  if (std::count(args.Positional.begin(), args.Positional.end(), "-") > 1)
  {
    throw UsageError("INPUT and CURVE cannot both be - (stdin)");
  }
  const std::string output = args.Value("output", "");
  if (!output.empty())
  {
    CheckNotAnInput(output, args.Positional);
  }
  vtkNew<vtkPolylineShapeAnalysis> analysis;
  analysis->SetClosed(args.Flag("closed"));
  SET_FROM_OPTION(args, analysis, "data-tolerance", DataShapeTolerance);
  SET_FROM_OPTION(args, analysis, "curve-tolerance", CurveShapeTolerance);
  const std::string lineColumn = args.Value("line-column", "");
  const bool quiet = args.Flag("quiet");
  args.RejectUnused();
  if (!output.empty())
  {
    CheckWritable(output);
  }

  const std::string input = args.Positional[0];
  const std::string curvePath = args.Positional.size() == 2 ? args.Positional[1] : "";
  vtkSmartPointer<vtkPolyData> data = Read(input, lineColumn);
  analysis->SetInputData(0, data);
  vtkSmartPointer<vtkPolyData> curve;
  if (args.Positional.size() == 2)
  {
    curve = ReadFittedCurve(curvePath, input, data);
    analysis->SetInputData(1, curve);
  }
  MessageCounter messages({ analysis });
  analysis->Update();
  vtkPolyData* result = analysis->GetOutput();

  std::ostream silent(nullptr);
  // With the result on stdout, the summary goes to stderr.
  std::ostream& summary = quiet ? silent : output == "-" ? std::cerr : std::cout;
  CheckAudited(SummarizeAudit(result, curve, summary), curvePath, input);
  if (!output.empty())
  {
    Write(result, output);
    summary << "wrote " << (output == "-" ? "stdout" : output) << "\n";
  }
  return messages.Errors > 0 ? 2 : 0;
}
} // namespace

int main(int argc, char* argv[])
{
  // Messages go through the observers above, not VTK's default window; those no
  // observer takes (a reader's XML parser's) are printed alike, not as VTK's log.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkLogger::AddCallback("shapesplines",
    [](void*, const vtkLogger::Message& message) {
      std::cerr << (message.verbosity <= vtkLogger::VERBOSITY_ERROR ? "error: " : "warning: ")
                << MessageText(message.message) << '\n';
    },
    nullptr, vtkLogger::VERBOSITY_WARNING);
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "-h" || command == "--help" || command == "help")
  {
    std::cout << Usage;
    return 0;
  }
  if (command == "--version")
  {
    std::cout << Version;
    return 0;
  }
  try
  {
    Arguments args = Parse(argc, argv);
    if (args.Flag("help"))
    {
      std::cout << Usage;
      return 0;
    }
    if (args.Flag("version"))
    {
      std::cout << Version;
      return 0;
    }
    if (command == "fit")
    {
      return Fit(args);
    }
    if (command == "audit")
    {
      return Audit(args);
    }
    throw UsageError(command.empty() ? "no command given" : "unknown command '" + command + "'");
  }
  catch (const UsageError& e)
  {
    std::cerr << "shapesplines: " << e.what() << "\nRun 'shapesplines --help' for usage.\n";
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "shapesplines: " << e.what() << "\n";
    return 1;
  }
}
