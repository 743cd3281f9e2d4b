// TextReader: a whitespace-separated token reader over a whole text file, for the readers of our
// own formats (TetGen, Medit, VTK). It knows line numbers, so every error names the file and the
// line ("'f.ele' line 12: expected a vertex index, got 'x'"). '#' starts a comment to the end of
// the line when comments are enabled. Never reads past the end; never trusts a count.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace cvtmesh {

class TextReader {
 public:
  // Reads the file; throws InputError if it cannot be read, is empty or contains a NUL byte.
  explicit TextReader(const std::string& path, bool hash_comments = true);

  const std::string& path() const { return path_; }
  int line() const { return line_; }
  bool at_end();  // skips whitespace and comments first

  // The next token; throws InputError("... unexpected end of file, expected <what>") at the end.
  std::string_view token(const std::string& what);
  // The rest of the current line (without the newline), for line-oriented headers.
  std::string rest_of_line();
  // Numbers: the whole token must parse. Integers must fit in [lo, hi].
  long long integer(const std::string& what, long long lo, long long hi);
  double real(const std::string& what, bool finite = true);

  // Throws InputError("'<path>' line <n>: <message>").
  [[noreturn]] void fail(const std::string& message) const;
  // Bounds a declared count by what the rest of the file can hold (each item needs at least
  // `min_tokens` tokens): throws "... declares N <what>, but the file is too short".
  void check_count(long long count, int min_tokens, const std::string& what);

 private:
  void skip_space();
  std::string path_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool comments_;
};

}  // namespace cvtmesh
