#include "core/io/text_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/util/error.h"

namespace cvtmesh {

TextReader::TextReader(const std::string& path, bool hash_comments)
    : path_(path), comments_(hash_comments) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': cannot open the file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError("cannot read '" + path + "': I/O error");
  text_ = ss.str();
  if (text_.empty()) throw InputError("cannot read '" + path + "': the file is empty");
  const std::size_t nul = text_.find('\0');
  if (nul != std::string::npos) {
    line_ = 1;
    for (std::size_t i = 0; i < nul; ++i) line_ += text_[i] == '\n';
    fail("binary data (NUL byte) in a text file");
  }
}

void TextReader::fail(const std::string& message) const {
  throw InputError("'" + path_ + "' line " + std::to_string(line_) + ": " + message);
}

void TextReader::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (comments_ && c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      break;
    }
  }
}

bool TextReader::at_end() {
  skip_space();
  return pos_ >= text_.size();
}

std::string_view TextReader::token(const std::string& what) {
  skip_space();
  if (pos_ >= text_.size()) fail("unexpected end of file, expected " + what + " (truncated file?)");
  const std::size_t start = pos_;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') break;
    if (comments_ && c == '#') break;
    ++pos_;
  }
  return std::string_view(text_).substr(start, pos_ - start);
}

std::string TextReader::rest_of_line() {
  const std::size_t start = pos_;
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  std::string r = text_.substr(start, pos_ - start);
  if (!r.empty() && r.back() == '\r') r.pop_back();
  if (pos_ < text_.size()) {
    ++pos_;
    ++line_;
  }
  return r;
}

namespace {
std::string shown(std::string_view t) {
  std::string s(t.substr(0, 40));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return "'" + s + (t.size() > 40 ? "...'" : "'");
}
}  // namespace

long long TextReader::integer(const std::string& what, long long lo, long long hi) {
  const std::string_view t = token(what);
  long long v = 0;
  const char* b = t.data();
  const char* e = b + t.size();
  if (b != e && *b == '+') ++b;
  const auto [p, ec] = std::from_chars(b, e, v);
  if (ec == std::errc::result_out_of_range) fail(what + " " + shown(t) + " is out of range");
  if (ec != std::errc() || p != e) fail("expected " + what + " (an integer), got " + shown(t));
  if (v < lo || v > hi)
    fail(what + " " + std::to_string(v) + " is out of range [" + std::to_string(lo) + ", " +
         std::to_string(hi) + "]");
  return v;
}

double TextReader::real(const std::string& what, bool finite) {
  const std::string_view t = token(what);
  const std::string str(t);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(str.c_str(), &end);
  if (end != str.c_str() + str.size() || str.empty())
    fail("expected " + what + " (a number), got " + shown(t));
  if (finite && !std::isfinite(v)) fail(what + " " + shown(t) + " is not a finite number");
  return v;
}

void TextReader::check_count(long long count, int min_tokens, const std::string& what) {
  // Every token takes at least 2 bytes (itself and a separator), except possibly the last.
  const long long room = static_cast<long long>(text_.size() - pos_) / 2 + 1;
  if (count < 0) fail("negative number of " + what);
  if (min_tokens > 0 && count > room / min_tokens)
    fail("declares " + std::to_string(count) + " " + what +
         ", but the file is too short (truncated file?)");
}

}  // namespace cvtmesh
