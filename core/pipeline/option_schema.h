// The options of optimize(), each declared once (geogram's declare_arg is the model): its name
// (the Python keyword and JSON key), its CLI flag, its GUI panel label, type, range, the
// dimensions it applies to and its help. The default is the value of the field in a
// default-constructed OptimizeOptions (core/pipeline/optimize.h), read from there. Every front
// end (the CLI flags, the Python keyword arguments and docstring, the GUI/ONELAB panel, the
// benchmarks) builds its inputs from this table; optimize() itself calls validate(), so a bad
// value is refused with the same OptionError whatever front end it came through.
// Adding an option: docs/architecture.md, "Adding an option".
#pragma once
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/util/error.h"

namespace cvtmesh {

struct OptimizeOptions;

// A value refused by validate(): names the option, the value and what is allowed. An InputError
// (the CLI exits 2, Python raises cvtmesh.InputError, a ValueError).
class OptionError : public InputError {
 public:
  OptionError(std::string option, std::string value, const std::string& message)
      : InputError(message), option_(std::move(option)), value_(std::move(value)) {}
  const std::string& option() const { return option_; }
  const std::string& value() const { return value_; }

 private:
  std::string option_, value_;
};

enum OptionDims : int { kDim2 = 1, kDim3 = 2, kDim23 = 3 };
// Which front ends show an option (all of them validate it through optimize()).
enum OptionFront : int { kCli = 1, kPython = 2, kPanel = 4, kAllFronts = 7 };

using OptionField =
    std::variant<int OptimizeOptions::*, unsigned OptimizeOptions::*, double OptimizeOptions::*,
                 bool OptimizeOptions::*, std::string OptimizeOptions::*>;

struct OptionSpec {
  std::string name;   // "max_iterations": Python keyword, JSON key, name in messages
  std::string flag;   // "--max-iterations"; a bool whose flag starts "--no-" sets it false
  std::string panel;  // GUI panel label ("" = not in the panel), sorted by its leading digit
  OptionField field;
  int dims = kDim23;  // dimensions it applies to: a non-default value elsewhere is refused
  int fronts = kAllFronts;
  double min = 0, max = 0;  // numbers: the allowed closed range (max may be +inf)
  double special = 0;       // numbers: a value outside the range that means "default"
  bool has_special = false;
  std::vector<std::string> choices;  // strings: the allowed values (empty: see validate)
  // strings: a value other than the choices is the path of a file the front end reads (sizing:
  // OptimizeOptions::sizing_reference); what it holds is checked by the reader, not here.
  bool or_path = false;
  std::string help;  // one sentence, no default or range (added by describe)
};

// The whole schema, in the order front ends list it.
const std::vector<OptionSpec>& option_schema();

// The option named `name` (or whose flag is `name`), or null.
const OptionSpec* find_option(std::string_view name);

// The value of o's field as text ("1.5", "true", "mesh"); the default: value_text(s, {}).
std::string value_text(const OptionSpec& s, const OptimizeOptions& o);
// True if o's field holds the default value.
bool is_default(const OptionSpec& s, const OptimizeOptions& o);
// Numbers and bools as a double (bools 0/1); throws std::logic_error for a string option.
double value_number(const OptionSpec& s, const OptimizeOptions& o);
// Sets o's field from a number (ints and unsigned must be whole; bools 0/1) or text; throws
// OptionError for a value of the wrong type, before any range check.
void set_number(const OptionSpec& s, OptimizeOptions& o, double v);
void set_text(const OptionSpec& s, OptimizeOptions& o, const std::string& v);

// "help (default D; range [a, b])": the help line every front end prints.
std::string describe(const OptionSpec& s);

// Checks every option of o for a mesh of dimension dim (2 or 3; 0: either): types, ranges,
// choices, the method against the registry, options that do not apply to dim left at their
// default, a sizing path with its reference mesh read (of dimension dim). Throws OptionError
// naming the first bad option.
void validate(const OptimizeOptions& o, int dim);

// True if o.sizing names a reference file (not one of the sizing keywords).
bool sizing_is_path(const OptimizeOptions& o);

// o with the "default" values resolved for dimension dim: an empty method (or the 3D default in
// 2D) becomes the dimension's default method, lbfgs_memory -1 the dimension's memory.
OptimizeOptions resolve(const OptimizeOptions& o, int dim);

// Named settings of the Lloyd step offered together (the GUI's "Lloyd step" menu; the paper's
// plain Lloyd for the reproduction drivers): "default", "L-BFGS", "Anderson", "plain (paper)".
struct OptionPreset {
  std::string name, help;
  std::vector<std::pair<std::string, double>> values;  // option name, value
};
const std::vector<OptionPreset>& lloyd_step_presets();
// Applies the preset named `name` to o; throws OptionError for an unknown one.
void apply_preset(const std::string& name, OptimizeOptions& o);

}  // namespace cvtmesh
