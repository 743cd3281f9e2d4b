#include "core/io/geo_scan.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;

struct Token {
  enum Kind { kIdent, kString, kPunct, kNumber, kEnd } kind = kEnd;
  std::string text;  // identifier, unescaped string, or the punctuation character
  int line = 0;
};

// Gmsh.l's lexical rules: /* */ and // comments, "..." strings with backslash escapes,
// identifiers [A-Za-z_][A-Za-z0-9_]*; everything else is a one-character token.
std::vector<Token> lex(const std::string& s) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = s.size();
  while (i < n) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '/' && i + 1 < n && s[i + 1] == '/') {
      while (i < n && s[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && s[i + 1] == '*') {
      i += 2;
      while (i < n && !(s[i] == '*' && i + 1 < n && s[i + 1] == '/')) {
        if (s[i] == '\n') ++line;
        ++i;
      }
      i = std::min(n, i + 2);
    } else if (c == '"') {
      Token t{Token::kString, "", line};
      ++i;
      while (i < n && s[i] != '"') {
        if (s[i] == '\\' && i + 1 < n) {
          ++i;
          t.text += s[i] == 'n' ? '\n' : s[i] == 't' ? '\t' : s[i];
        } else {
          t.text += s[i];
        }
        if (s[i] == '\n') ++line;
        ++i;
      }
      ++i;
      out.push_back(t);
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      Token t{Token::kIdent, "", line};
      while (i < n && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_'))
        t.text += s[i++];
      out.push_back(t);
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      Token t{Token::kNumber, "", line};
      while (i < n && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '.'))
        t.text += s[i++];
      out.push_back(t);
    } else {
      out.push_back({Token::kPunct, std::string(1, c), line});
      ++i;
    }
  }
  out.push_back({Token::kEnd, "", line});
  return out;
}

const std::set<std::string> kProcessCommands = {"SystemCall", "NonBlockingSystemCall", "OnelabRun"};

class Scanner {
 public:
  Scanner(std::vector<GeoScanFinding>& findings, std::map<std::string, std::string> strings)
      : findings_(findings), strings_(std::move(strings)) {
    for (const auto& [name, value] : strings_) set_from_command_line_.insert(name);
  }

  void scan_file(const std::string& path, int depth) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(fs::absolute(path), ec);
    const std::string key = ec ? path : canonical.string();
    if (!visited_.insert(key).second) return;
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // Gmsh reports a missing or unreadable file itself
    if (depth > 64) {
      findings_.push_back({path, 0, "Include", "includes nested more than 64 deep"});
      return;
    }
    std::ostringstream text;
    text << in.rdbuf();
    const std::vector<Token> toks = lex(text.str());
    const std::string dir = fs::path(key).parent_path().string() + "/";
    for (std::size_t i = 0; i < toks.size(); ++i) {
      const Token& t = toks[i];
      if (t.kind != Token::kIdent) continue;
      if (kProcessCommands.count(t.text)) {
        findings_.push_back({path, t.line, t.text, statement_text(toks, i + 1)});
      } else if (t.text == "Solver" && i + 2 < toks.size() && toks[i + 1].text == "." &&
                 toks[i + 2].kind == Token::kIdent &&
                 toks[i + 2].text.rfind("Executable", 0) == 0) {
        findings_.push_back(
            {path, t.line, "Solver." + toks[i + 2].text,
             "registers a program for Gmsh to run: " + statement_text(toks, i + 3)});
      } else if (t.text == "Include" || t.text == "Merge" || t.text == "MergeWithBoundingBox") {
        std::size_t j = i + 1;
        std::string name;
        if (!eval(toks, j, dir, key, name)) {
          findings_.push_back(
              {path, t.line, t.text,
               "a computed file name the scan cannot follow: " + statement_text(toks, i + 1)});
          continue;
        }
        if (!name.empty() && name[0] != '/') name = dir + name;
        const std::string ext = fs::path(name).extension().string();
        if (t.text == "Include" || gmsh_parses_as_script(ext)) {
          scan_file(name, depth + 1);
          scan_file(name + ".opt", depth + 1);
        }
      } else if (i + 2 < toks.size() && toks[i + 1].text == "=" &&
                 !(i > 0 && toks[i - 1].text == ".")) {
        // A string variable: name = <string expr>; or name = DefineString[<string expr>, ...];
        std::size_t j = i + 2;
        std::string value;
        if (toks[j].kind == Token::kIdent && toks[j].text == "DefineString" &&
            toks[j + 1].text == "[") {
          j += 2;
          if (eval(toks, j, dir, key, value) && !set_from_command_line_.count(t.text))
            strings_[t.text] = value;
        } else if (eval(toks, j, dir, key, value) && toks[j].text == ";") {
          strings_[t.text] = value;
          set_from_command_line_.erase(t.text);
        }
      }
    }
  }

 private:
  // A string expression at toks[j] (advances j past it): "literal", CurrentDir, CurrentFileName,
  // a known string variable, StrCat/Str(e, ...), StrPrefix(e), StrRelative(e).
  bool eval(const std::vector<Token>& toks, std::size_t& j, const std::string& dir,
            const std::string& file, std::string& out) {
    const Token& t = toks[j];
    if (t.kind == Token::kString) {
      out = t.text;
      ++j;
      return true;
    }
    if (t.kind != Token::kIdent) return false;
    if (t.text == "CurrentDir" || t.text == "CurrentDirectory") {
      out = dir;
      ++j;
      return true;
    }
    if (t.text == "CurrentFileName") {
      out = fs::path(file).filename().string();
      ++j;
      return true;
    }
    const bool call = toks[j + 1].text == "(";
    if (!call) {
      auto it = strings_.find(t.text);
      if (it == strings_.end()) return false;
      out = it->second;
      ++j;
      return true;
    }
    const std::string f = t.text;
    if (f != "StrCat" && f != "Str" && f != "StrPrefix" && f != "StrRelative") return false;
    j += 2;
    std::vector<std::string> args;
    while (true) {
      std::string a;
      if (!eval(toks, j, dir, file, a)) return false;
      args.push_back(a);
      if (toks[j].text == ",") {
        ++j;
        continue;
      }
      if (toks[j].text != ")") return false;
      ++j;
      break;
    }
    out.clear();
    if (f == "StrCat" || f == "Str") {
      for (const auto& a : args) out += a;
    } else if (args.size() == 1) {
      const fs::path p(args[0]);
      out = f == "StrPrefix" ? (p.parent_path() / p.stem()).string() : p.filename().string();
    } else {
      return false;
    }
    return true;
  }

  // The tokens of a statement from toks[j] to its ';', as one line of text (for messages).
  static std::string statement_text(const std::vector<Token>& toks, std::size_t j) {
    std::string s;
    for (; j < toks.size() && toks[j].kind != Token::kEnd && toks[j].text != ";"; ++j) {
      if (s.size() > 120) {
        s += " ...";
        break;
      }
      const Token& t = toks[j];
      if (!s.empty() && t.kind != Token::kPunct && s.back() != '(') s += ' ';
      s += t.kind == Token::kString ? "\"" + t.text + "\"" : t.text;
    }
    return s;
  }

  std::vector<GeoScanFinding>& findings_;
  std::map<std::string, std::string> strings_;
  std::set<std::string> set_from_command_line_;
  std::set<std::string> visited_;
};

}  // namespace

bool gmsh_parses_as_script(const std::string& extension) {
  std::string e;
  for (char c : extension) e += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const std::set<std::string> data = {
      ".msh", ".stl",  ".step", ".stp", ".brep", ".brp",  ".iges", ".igs",  ".unv",  ".vtk",
      ".vtu", ".mesh", ".bdf",  ".nas", ".p3d",  ".ply",  ".ply2", ".med",  ".rmed", ".mmed",
      ".inp", ".off",  ".obj",  ".x3d", ".wrl",  ".vrml", ".cgns", ".diff", ".neu",  ".png",
      ".jpg", ".jpeg", ".bmp",  ".pnm", ".ppm",  ".pgm",  ".pbm",  ".mpg",  ".pdf",  ".svg",
      ".xyz", ".node", ".ele",  ".tet", ".dat",  ".txt",  ".csv"};
  return !data.count(e);
}

std::vector<GeoScanFinding> scan_geo_for_processes(
    const std::string& path, const std::vector<std::pair<std::string, std::string>>& set_strings) {
  std::vector<GeoScanFinding> findings;
  std::map<std::string, std::string> strings(set_strings.begin(), set_strings.end());
  Scanner scanner(findings, std::move(strings));
  scanner.scan_file(path, 0);
  scanner.scan_file(path + ".opt", 1);
  return findings;
}

std::string geo_scan_message(const std::vector<GeoScanFinding>& findings) {
  if (findings.empty()) return "";
  const GeoScanFinding& f = findings.front();
  std::string m = "'" + f.file + "'";
  if (f.line > 0) m += " line " + std::to_string(f.line);
  m += ": " + f.command;
  if (!f.detail.empty()) m += " " + f.detail;
  if (f.command == "Include" || f.command == "Merge" || f.command == "MergeWithBoundingBox")
    m += " (a script it pulls in could start programs)";
  else
    m += " (starts a program)";
  if (findings.size() > 1) m += ", and " + std::to_string(findings.size() - 1) + " more";
  m += "; refused: cvtmesh does not run programs from model files unless given "
       "--allow-system-calls (docs/reliability.md, Security)";
  return m;
}

}  // namespace cvtmesh
