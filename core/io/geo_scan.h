// Refusing .geo scripts that start processes, before Gmsh parses them (issue 18;
// docs/reliability.md, "Security"). Gmsh's .geo language can run programs (SystemCall,
// NonBlockingSystemCall, OnelabRun) and pull in further files that can (Include, Merge of a script,
// the file's own
// `<file>.opt`), and Gmsh 4.8 has no option to forbid it. The scan follows Gmsh's lexical rules
// (// and /* */ comments, "strings" with backslash escapes, identifiers are case-sensitive) and
// resolves the file names of Include/Merge as Gmsh does: string literals, CurrentDir,
// StrCat(...)/StrPrefix/StrRelative of those, string variables assigned from them (`s = "...";`,
// DefineString["..."]) and the strings set from the command line. A name it cannot resolve is
// itself refused: the scan never guesses.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace cvtmesh {

struct GeoScanFinding {
  std::string file;     // the script that holds it
  int line = 0;         // 1-based
  std::string command;  // "SystemCall", "NonBlockingSystemCall", "OnelabRun", or "Include"/"Merge"
  std::string detail;   // the command's argument as written, or why the file name is unknown
};

// Scans `path` and, recursively, every script it Includes or Merges (and each one's `.opt`
// file). `set_strings` are the string parameters set before parsing (ReadOptions::set_strings).
// Returns every finding (empty: nothing starts a process). Unreadable included files are findings
// too (Gmsh would fail on them anyway).
std::vector<GeoScanFinding> scan_geo_for_processes(
    const std::string& path,
    const std::vector<std::pair<std::string, std::string>>& set_strings = {});

// True if Gmsh parses a file of this extension (".geo", "" or any extension Gmsh does not read as
// data: Gmsh falls back to its script parser) as a script; false for mesh/CAD/image data.
bool gmsh_parses_as_script(const std::string& extension);

// The message for the first finding, naming the file, the line and the command, and the way out.
std::string geo_scan_message(const std::vector<GeoScanFinding>& findings);

}  // namespace cvtmesh
