// Reading one JSON object of a scene file: typed, range-checked values whose errors start with
// the value's JSON path ("particles[3].mass = -1: must be finite and positive"), and a check
// that rejects the keys nobody asked for. Used by the scene and composite-body files.
#pragma once

#include <impetus/error.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace impetus::cli::json_fields {

using nlohmann::json;

/// Throws impetus::Error("<field>: <message>").
[[noreturn]] inline void fail(const std::string& field, const std::string& message) {
  throw Error(field, field + ": " + message);
}

/// The contents of a text file; an unreadable file is an impetus::Error naming the path.
std::string readFile(const std::string& path);

/// Parses a JSON document that must be an object; malformed JSON and any other top-level value
/// are impetus::Errors ("json: malformed JSON: ...", "document: expected ...").
json parseObject(const std::string& text, const std::string& expectation);

/// A top-level array of a scene document and the most elements it may hold.
struct ArrayLimit {
  const char* key;   ///< e.g. "bodies"
  std::size_t limit; ///< e.g. 1,000,000
};

/// Refuses a document whose top-level array `key` holds more than `limit` elements, as the
/// loader would ("bodies[1000000]: more than 1000000 bodies in the scene"), but from one pass
/// over the text that builds nothing: a million-body file is refused in a fraction of the time
/// and none of the memory its document would take. Malformed JSON is left to parseObject.
void requireArrayLimits(const std::string& text, std::initializer_list<ArrayLimit> limits);

/// "where[i]": the path of an array element.
inline std::string index(const std::string& where, std::size_t i) { return where + "[" + std::to_string(i) + "]"; }

/// Typed values from one JSON object at `where`; it remembers every key asked for (present or
/// not), and done() rejects the keys nobody asked for, naming the ones it knows.
class Fields {
public:
  Fields(const json& object, std::string where) : object_(object), where_(std::move(where)) {
    if (!object_.is_object()) {
      fail(where_, "expected an object, got " + object_.dump());
    }
  }

  [[nodiscard]] const std::string& where() const { return where_; }
  [[nodiscard]] std::string path(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }

  [[nodiscard]] bool has(const std::string& key) {
    known_.insert(key);
    return object_.contains(key);
  }
  [[nodiscard]] const json* find(const std::string& key) { return has(key) ? &object_.at(key) : nullptr; }
  [[nodiscard]] const json& require(const std::string& key) {
    if (!has(key)) {
      fail(path(key), "missing");
    }
    return object_.at(key);
  }

  [[nodiscard]] double number(const std::string& key, double fallback) {
    const json* j = find(key);
    return j != nullptr ? numberAt(*j, path(key)) : fallback;
  }
  [[nodiscard]] double requiredNumber(const std::string& key) { return numberAt(require(key), path(key)); }
  [[nodiscard]] float positive(const std::string& key, double fallback) {
    return narrow(requirePositive(number(key, fallback), path(key)), path(key));
  }
  [[nodiscard]] float nonNegative(const std::string& key, double fallback) {
    return narrow(requireNonNegative(number(key, fallback), path(key)), path(key));
  }
  [[nodiscard]] float fraction(const std::string& key, double fallback) {
    const double v = number(key, fallback);
    if (!(v >= 0.0 && v <= 1.0)) {
      throwInvalid(path(key), v, "must be in [0, 1]");
    }
    return static_cast<float>(v);
  }
  [[nodiscard]] float real(const std::string& key, double fallback) { return narrow(number(key, fallback), path(key)); }
  [[nodiscard]] float requiredReal(const std::string& key) { return narrow(requiredNumber(key), path(key)); }
  [[nodiscard]] float requiredPositive(const std::string& key) {
    return narrow(requirePositive(requiredNumber(key), path(key)), path(key));
  }
  [[nodiscard]] Vec3f vec3(const std::string& key, const Vec3f& fallback) {
    const json* j = find(key);
    return j != nullptr ? vec3At(*j, path(key)) : fallback;
  }
  [[nodiscard]] Vec3f requiredVec3(const std::string& key) { return vec3At(require(key), path(key)); }
  [[nodiscard]] std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) {
    const json* j = find(key);
    return j != nullptr ? integerAt(*j, path(key), lo, hi) : fallback;
  }
  [[nodiscard]] bool boolean(const std::string& key, bool fallback) {
    const json* j = find(key);
    if (j == nullptr) {
      return fallback;
    }
    if (!j->is_boolean()) {
      fail(path(key), "expected true or false, got " + j->dump());
    }
    return j->get<bool>();
  }
  [[nodiscard]] std::string text(const std::string& key, const std::string& fallback) {
    const json* j = find(key);
    if (j == nullptr) {
      return fallback;
    }
    if (!j->is_string()) {
      fail(path(key), "expected a string, got " + j->dump());
    }
    return j->get<std::string>();
  }

  /// Rejects the keys that were never asked for.
  void done() const {
    for (const auto& item : object_.items()) {
      if (!known_.contains(item.key())) {
        std::string list;
        for (const std::string& k : known_) {
          list += (list.empty() ? "" : ", ") + k;
        }
        fail(path(item.key()), "unknown key (expected one of: " + list + ")");
      }
    }
  }

  static double numberAt(const json& j, const std::string& field) {
    if (!j.is_number()) {
      fail(field, "expected a number, got " + j.dump());
    }
    return requireFinite(j.get<double>(), field);
  }
  /// A double that fits a float (the world's scalar).
  static float narrow(double v, const std::string& field) {
    if (std::abs(v) > static_cast<double>(std::numeric_limits<float>::max())) {
      throwInvalid(field, v, "is out of range (single precision)");
    }
    return static_cast<float>(v);
  }
  static Vec3f vec3At(const json& j, const std::string& field) {
    if (!j.is_array() || j.size() != 3) {
      fail(field, "expected an array of 3 numbers, got " + j.dump());
    }
    return {narrow(numberAt(j[0], field + "[0]"), field + "[0]"), narrow(numberAt(j[1], field + "[1]"), field + "[1]"),
            narrow(numberAt(j[2], field + "[2]"), field + "[2]")};
  }
  static std::int64_t integerAt(const json& j, const std::string& field, std::int64_t lo, std::int64_t hi) {
    if (!j.is_number_integer()) {
      fail(field, "expected a whole number, got " + j.dump());
    }
    const std::int64_t v = j.get<std::int64_t>();
    if (v < lo || v > hi) {
      throwInvalid(field, static_cast<double>(v),
                   "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    }
    return v;
  }

private:
  const json& object_;
  std::string where_;
  std::set<std::string> known_;
};

/// "localAnchorA" -> "local_anchor_a": the library's field names as the files spell them.
inline std::string snakeCase(const std::string& name) {
  std::string out;
  for (const char c : name) {
    if (std::isupper(static_cast<unsigned char>(c)) != 0) {
      out.push_back('_');
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    } else {
      out.push_back(c);
    }
  }
  return out;
}

/// Runs `build`, re-labelling an impetus::Error raised by the library ("mass = -1: ...") with
/// the element's JSON path ("particles[3].mass = -1: ...").
/// A library field's name in the file's words: {"halfWidth", "half_extents[0]"}.
struct FieldName {
  const char* library;
  const char* file;
};

/// The file's word for a library field: the renamed one if listed, else its snake_case.
inline std::string fileFieldName(const std::string& library, std::initializer_list<FieldName> renames) {
  for (const FieldName& r : renames) {
    if (library == r.library) {
      return r.file;
    }
  }
  return snakeCase(library);
}

/// Runs `build`; an impetus::Error it raises is re-raised under `where`, its field in the file's
/// words (`renames` for the fields the file spells differently from the library).
template <class F> auto at(const std::string& where, F&& build, std::initializer_list<FieldName> renames = {}) {
  try {
    return build();
  } catch (const Error& e) {
    const std::string field = fileFieldName(e.field(), renames);
    const std::string message = e.what();
    const std::string rest = message.rfind(e.field(), 0) == 0 ? message.substr(e.field().size()) : ": " + message;
    throw Error(where + "." + field, where + "." + field + rest);
  }
}

/// The elements of an optional top-level array.
inline const json& arrayOf(const json& doc, const std::string& key) {
  static const json empty = json::array();
  if (!doc.contains(key)) {
    return empty;
  }
  const json& a = doc.at(key);
  if (!a.is_array()) {
    fail(key, "expected an array, got " + a.dump());
  }
  return a;
}

} // namespace impetus::cli::json_fields

namespace impetus::cli::json_fields {

/// Calls each(element, "key[i]") for every element of the optional top-level array `key`.
template <class F> void forEach(const json& doc, const std::string& key, F&& each) {
  const json& items = arrayOf(doc, key);
  for (std::size_t i = 0; i < items.size(); ++i) {
    each(items[i], index(key, i));
  }
}

/// 2D values, lists of points, angles in degrees, bit fields and words of a closed set, for the
/// 2D scene files.
inline Vec2f vec2At(const json& j, const std::string& field) {
  if (!j.is_array() || j.size() != 2) {
    fail(field, "expected an array of 2 numbers, got " + j.dump());
  }
  return {Fields::narrow(Fields::numberAt(j[0], field + "[0]"), field + "[0]"),
          Fields::narrow(Fields::numberAt(j[1], field + "[1]"), field + "[1]")};
}
inline Vec2f vec2(Fields& f, const std::string& key, const Vec2f& fallback) {
  const json* j = f.find(key);
  return j != nullptr ? vec2At(*j, f.path(key)) : fallback;
}
inline Vec2f requiredVec2(Fields& f, const std::string& key) { return vec2At(f.require(key), f.path(key)); }

/// A list of points [[x, y], ...] with between lo and hi entries.
inline std::vector<Vec2f> points(Fields& f, const std::string& key, std::size_t lo, std::size_t hi) {
  const json& j = f.require(key);
  const std::string field = f.path(key);
  if (!j.is_array()) {
    fail(field, "expected an array of [x, y] points, got " + j.dump());
  }
  if (j.size() < lo || j.size() > hi) {
    fail(field,
         "expected " + std::to_string(lo) + " to " + std::to_string(hi) + " points, got " + std::to_string(j.size()));
  }
  std::vector<Vec2f> out;
  out.reserve(j.size());
  for (std::size_t k = 0; k < j.size(); ++k) {
    out.push_back(vec2At(j[k], index(field, k)));
  }
  return out;
}

/// An angle given in degrees (key ends in _deg), in radians.
inline float angleDeg(Fields& f, const std::string& key, float fallbackRad) {
  return f.has(key) ? degToRad(f.real(key, 0.0)) : fallbackRad;
}

/// A collision bit field: a whole number in [0, 2^64 - 1].
inline std::uint64_t bits(Fields& f, const std::string& key, std::uint64_t fallback) {
  const json* j = f.find(key);
  if (j == nullptr) {
    return fallback;
  }
  if (j->is_number_unsigned()) {
    return j->get<std::uint64_t>();
  }
  if (j->is_number_integer()) {
    throwInvalid(f.path(key), static_cast<double>(j->get<std::int64_t>()), "must be a whole number >= 0");
  }
  fail(f.path(key), "expected a whole number (a bit field), got " + j->dump());
}

/// One word of a closed set.
inline std::string choice(Fields& f, const std::string& key, const std::string& fallback,
                          std::initializer_list<const char*> allowed, const std::string& what) {
  std::string value = f.text(key, fallback);
  std::string list;
  for (const char* a : allowed) {
    if (value == a) {
      return value;
    }
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  fail(f.path(key), "unknown " + what + " '" + value + "' (" + list + ")");
}

/// The "type" of an element, required.
inline std::string typeOf(Fields& f, std::initializer_list<const char*> allowed, const std::string& what) {
  (void)f.require("type");
  return choice(f, "type", "", allowed, what);
}

} // namespace impetus::cli::json_fields
