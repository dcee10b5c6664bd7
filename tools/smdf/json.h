// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf: the JSON value every subcommand returns, and its writer.

#ifndef SMDF_CLI_JSON_H
#define SMDF_CLI_JSON_H

#include <cmath>
#include <cstddef>
#include <locale>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace smdf_cli {

// A JSON value with insertion-ordered objects. Reals are written with 17 significant digits;
// non-finite reals, which JSON cannot represent, are written as null.
class Json
{
public:
  Json() : type_(NUL) {}
  Json(bool b) : type_(BOOL), bool_(b) {}
  template <typename T,
            typename std::enable_if<std::is_integral<T>::value && !std::is_same<T, bool>::value,
                                    int>::type = 0>
  Json(T v) : type_(std::is_signed<T>::value ? INT : UINT), int_(static_cast<long long>(v)),
              uint_(static_cast<unsigned long long>(v)) {}
  Json(double d) : type_(REAL), real_(d) {}
  Json(const char* s) : type_(STRING), string_(s) {}
  Json(std::string s) : type_(STRING), string_(std::move(s)) {}

  static Json array() { Json j; j.type_ = ARRAY; return j; }
  static Json object() { Json j; j.type_ = OBJECT; return j; }
  // [a, b]: vertex pairs, 2D vectors, ...
  template <typename A, typename B>
  static Json pair(const A& a, const B& b) { Json j = array(); j.push_back(a); j.push_back(b); return j; }

  // Appends to an array.
  Json& push_back(Json v)
  {
    require(ARRAY);
    items_.push_back(std::move(v));
    return items_.back();
  }
  // The length of an array.
  std::size_t size() const { return items_.size(); }
  // Member of an object, appended (null) if absent.
  Json& operator[](const std::string& key)
  {
    require(OBJECT);
    for(std::size_t i = 0; i < keys_.size(); ++i)
      if(keys_[i] == key) return items_[i];
    keys_.push_back(key);
    items_.emplace_back();
    return items_.back();
  }

  // Member of an object, or nullptr if absent or if this is not an object.
  const Json* find(const std::string& key) const
  {
    if(type_ != OBJECT) return nullptr;
    for(std::size_t i = 0; i < keys_.size(); ++i)
      if(keys_[i] == key) return &items_[i];
    return nullptr;
  }

  void write(std::ostream& os) const
  {
    switch(type_) {
      case NUL: os << "null"; break;
      case BOOL: os << (bool_ ? "true" : "false"); break;
      case INT: os << int_; break;
      case UINT: os << uint_; break;
      case REAL: write_real(os, real_); break;
      case STRING: write_string(os, string_); break;
      case ARRAY:
        os << '[';
        for(std::size_t i = 0; i < items_.size(); ++i) {
          if(i) os << ',';
          items_[i].write(os);
        }
        os << ']';
        break;
      case OBJECT:
        os << '{';
        for(std::size_t i = 0; i < items_.size(); ++i) {
          if(i) os << ',';
          write_string(os, keys_[i]);
          os << ':';
          items_[i].write(os);
        }
        os << '}';
        break;
    }
  }

  std::string str() const
  {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    write(os);
    return os.str();
  }

private:
  enum Type { NUL, BOOL, INT, UINT, REAL, STRING, ARRAY, OBJECT };
  Type type_;
  bool bool_ = false;
  long long int_ = 0;
  unsigned long long uint_ = 0;
  double real_ = 0;
  std::string string_;
  std::vector<Json> items_;        // array elements or object values
  std::vector<std::string> keys_;  // object keys

  void require(Type t) const
  {
    if(type_ != t) throw std::logic_error("Json: wrong value type for this operation");
  }

  static void write_real(std::ostream& os, double d)
  {
    if(!std::isfinite(d)) { os << "null"; return; }
    const std::streamsize old = os.precision(17);
    os << d;
    os.precision(old);
  }

  // Length of the valid UTF-8 sequence starting at s[i], or 0 if it is not valid.
  static std::size_t utf8_length(const std::string& s, std::size_t i)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t n;
    unsigned int cp;
    if(c < 0x80) return 1;
    else if((c & 0xE0) == 0xC0) { n = 2; cp = c & 0x1F; }
    else if((c & 0xF0) == 0xE0) { n = 3; cp = c & 0x0F; }
    else if((c & 0xF8) == 0xF0) { n = 4; cp = c & 0x07; }
    else return 0;
    if(i + n > s.size()) return 0;
    for(std::size_t k = 1; k < n; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + k]);
      if((d & 0xC0) != 0x80) return 0;
      cp = (cp << 6) | (d & 0x3F);
    }
    static const unsigned int min_cp[5] = {0, 0, 0x80, 0x800, 0x10000};
    if(cp < min_cp[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
  }

  // Quotes and escapes a string; bytes that are not valid UTF-8 become U+FFFD.
  static void write_string(std::ostream& os, const std::string& s)
  {
    os << '"';
    for(std::size_t i = 0; i < s.size();) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      switch(c) {
        case '"': os << "\\\""; ++i; continue;
        case '\\': os << "\\\\"; ++i; continue;
        case '\b': os << "\\b"; ++i; continue;
        case '\f': os << "\\f"; ++i; continue;
        case '\n': os << "\\n"; ++i; continue;
        case '\r': os << "\\r"; ++i; continue;
        case '\t': os << "\\t"; ++i; continue;
        default: break;
      }
      if(c < 0x20 || c == 0x7F) {
        static const char* hex = "0123456789abcdef";
        os << "\\u00" << hex[c >> 4] << hex[c & 15];
        ++i;
        continue;
      }
      const std::size_t n = utf8_length(s, i);
      if(n == 0) { os << "\\ufffd"; ++i; continue; }
      os.write(s.data() + i, std::streamsize(n));
      i += n;
    }
    os << '"';
  }
};

} // namespace smdf_cli

#endif // SMDF_CLI_JSON_H
