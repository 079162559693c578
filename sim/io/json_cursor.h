#pragma once
// The streaming scene reader's view of JSON text: a cursor that reads values in place, and the
// few kinds of value the scene's fields need. Anything else it meets makes it give up, and the
// reader that names errors (scene_file.cpp) takes over.

#include "sim/io/scene_file.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace carom::io::stream {

// Thrown on anything the reader leaves to parseScene's reader.
struct GiveUp {};
[[noreturn]] inline void giveUp() {
  throw GiveUp{};
}

// Deeper than this, Qt's parser refuses a document; so does this reader, earlier.
constexpr int kMaxDepth = 512;

inline bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// A JSON value as far as the scene's fields need it: a number, a string, an array of up to four
// numbers, or anything else (kept only as its text).
struct Value {
  enum class Kind { Number, String, Numbers, Other };
  Kind kind = Kind::Other;
  double number = 0.0;
  std::string text;
  std::array<double, 4> numbers{};
  int count = 0;
};

// A member of an object, with the text of `"key": value` as it is in the file.
struct Member {
  std::string key;
  Value value;
  std::string_view raw;
};

class Cursor {
 public:
  explicit Cursor(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  void skipSpace() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
  }
  bool atEnd() {
    skipSpace();
    return p_ == end_;
  }
  char peek() {
    skipSpace();
    if (p_ == end_) giveUp();
    return *p_;
  }
  bool accept(char c) {
    if (peek() != c) return false;
    ++p_;
    return true;
  }
  void expect(char c) {
    if (!accept(c)) giveUp();
  }
  const char* position() const { return p_; }
  void rewind(const char* to, std::size_t values) {
    p_ = to;
    values_ = values;
  }
  std::size_t values() const { return values_; }

  // Calls f(key) for each member of an object, with the cursor before its value, which f reads.
  template <typename F>
  void members(F&& f) {
    expect('{');
    countValue();
    if (accept('}')) return;
    do {
      skipSpace();
      const char* start = p_;
      std::string key;
      if (peek() != '"') giveUp();
      string(key);
      expect(':');
      f(key, start);
    } while (accept(','));
    expect('}');
  }

  // Calls f() for each element of an array, with the cursor before it.
  template <typename F>
  void elements(F&& f) {
    expect('[');
    countValue();
    if (accept(']')) return;
    do f();
    while (accept(','));
    expect(']');
  }

  double number() {
    skipSpace();
    const char* start = p_;
    if (p_ < end_ && *p_ == '-') ++p_;
    if (p_ == end_) giveUp();
    bool integral = true;
    if (*p_ == '0')
      ++p_;
    else if (*p_ >= '1' && *p_ <= '9')
      digits();
    else
      giveUp();
    if (p_ < end_ && *p_ == '.') {
      integral = false;
      ++p_;
      if (p_ == end_ || !isDigit(*p_)) giveUp();
      digits();
    }
    if (p_ < end_ && (*p_ == 'e' || *p_ == 'E')) {
      integral = false;
      ++p_;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !isDigit(*p_)) giveUp();
      digits();
    }
    double value = 0.0;
    // Beyond the doubles (or below them) the other reader decides, as Qt's parser does.
    const auto [end, error] = std::from_chars(start, p_, value);
    if (error != std::errc() || end != p_ || !std::isfinite(value)) giveUp();
    // Qt reads an integer as one: "-0" is a nought without a sign.
    if (integral && value == 0.0) value = 0.0;
    countValue();
    return value;
  }

  void stringValue(std::string& out) {
    if (peek() != '"') giveUp();
    string(out);
    countValue();
  }

  // Any value, checked as Qt's parser would check it, and keys appearing twice in an object.
  void skipValue(int depth = 0) {
    if (depth > kMaxDepth) giveUp();
    switch (peek()) {
      case '{': {
        std::vector<std::string> keys;
        members([&](const std::string& key, const char*) {
          if (std::find(keys.begin(), keys.end(), key) != keys.end()) giveUp();
          keys.push_back(key);
          skipValue(depth + 1);
        });
        return;
      }
      case '[':
        elements([&] { skipValue(depth + 1); });
        return;
      case '"': {
        std::string text;
        stringValue(text);
        return;
      }
      case 't':
        literal("true");
        return;
      case 'f':
        literal("false");
        return;
      case 'n':
        literal("null");
        return;
      default:
        number();
    }
  }

  // A member's value as a Value.
  void value(Value& out) {
    out.text.clear();
    out.count = 0;
    const char c = peek();
    if (c == '"') {
      out.kind = Value::Kind::String;
      stringValue(out.text);
    } else if (c == '-' || isDigit(c)) {
      out.kind = Value::Kind::Number;
      out.number = number();
    } else if (c == '[' && numberArray(out)) {
      out.kind = Value::Kind::Numbers;
    } else {
      out.kind = Value::Kind::Other;
      skipValue(1);
    }
  }

 private:
  void countValue() {
    if (++values_ > static_cast<std::size_t>(kMaxSceneValues)) giveUp();
  }
  void digits() {
    while (p_ < end_ && isDigit(*p_)) ++p_;
  }
  void literal(std::string_view word) {
    if (static_cast<std::size_t>(end_ - p_) < word.size() ||
        std::string_view(p_, word.size()) != word)
      giveUp();
    p_ += word.size();
    countValue();
  }

  // An array of one to four numbers; false, with nothing read, for any other array.
  bool numberArray(Value& out) {
    const char* start = p_;
    const std::size_t values = values_;
    expect('[');
    countValue();
    do {
      const char c = peek();
      if (out.count == 4 || !(c == '-' || isDigit(c))) {
        rewind(start, values);
        out.count = 0;
        return false;
      }
      out.numbers[out.count++] = number();
    } while (accept(','));
    expect(']');
    return true;
  }

  void string(std::string& out) {
    expect('"');
    for (;;) {
      const char* run = p_;
      while (p_ < end_) {
        const auto c = static_cast<unsigned char>(*p_);
        if (c < 0x20 || c >= 0x80 || c == '"' || c == '\\') break;
        ++p_;
      }
      out.append(run, p_);
      if (p_ == end_) giveUp();
      const auto c = static_cast<unsigned char>(*p_);
      if (c == '"') {
        ++p_;
        return;
      }
      if (c < 0x20) giveUp();
      if (c == '\\')
        escape(out);
      else
        utf8(out);
    }
  }

  void escape(std::string& out) {
    ++p_;  // the backslash
    if (p_ == end_) giveUp();
    const char c = *p_++;
    switch (c) {
      case '"':
      case '\\':
      case '/':
        out += c;
        return;
      case 'b':
        out += '\b';
        return;
      case 'f':
        out += '\f';
        return;
      case 'n':
        out += '\n';
        return;
      case 'r':
        out += '\r';
        return;
      case 't':
        out += '\t';
        return;
      case 'u':
        break;
      default:
        giveUp();
    }
    char32_t code = hex4();
    if (code >= 0xD800 && code <= 0xDBFF) {
      // A high surrogate must be followed by a low one; lone ones are left to Qt.
      if (end_ - p_ < 6 || p_[0] != '\\' || p_[1] != 'u') giveUp();
      p_ += 2;
      const char32_t low = hex4();
      if (low < 0xDC00 || low > 0xDFFF) giveUp();
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
    } else if (code >= 0xDC00 && code <= 0xDFFF) {
      giveUp();
    }
    append(out, code);
  }

  char32_t hex4() {
    if (end_ - p_ < 4) giveUp();
    char32_t code = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = *p_++;
      code <<= 4;
      if (isDigit(c))
        code |= static_cast<char32_t>(c - '0');
      else if (c >= 'a' && c <= 'f')
        code |= static_cast<char32_t>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F')
        code |= static_cast<char32_t>(c - 'A' + 10);
      else
        giveUp();
    }
    return code;
  }

  static void append(std::string& out, char32_t code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  // One character of two to four bytes, which must be well-formed UTF-8 of a character that is
  // neither a surrogate nor a non-character (those are left to Qt).
  void utf8(std::string& out) {
    const auto lead = static_cast<unsigned char>(*p_);
    int length = 0;
    char32_t code = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
      code = lead & 0x1F;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
      code = lead & 0x0F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
      code = lead & 0x07;
    } else {
      giveUp();
    }
    if (end_ - p_ < length) giveUp();
    for (int k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(p_[k]);
      if ((next & 0xC0) != 0x80) giveUp();
      code = (code << 6) | (next & 0x3F);
    }
    const char32_t least = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
    if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF) ||
        (code >= 0xFDD0 && code <= 0xFDEF) || (code & 0xFFFE) == 0xFFFE)
      giveUp();
    out.append(p_, p_ + length);
    p_ += length;
  }

  const char* p_;
  const char* end_;
  std::size_t values_ = 0;
};

}  // namespace carom::io::stream
