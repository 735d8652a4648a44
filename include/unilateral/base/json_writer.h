#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace unilateral
{
  /**
   * A JSON object whose keys keep the order in which they were added, for
   * summary.json. Values are numbers, strings, booleans, nested objects or
   * arrays of objects; that is all a run summary needs.
   */
  class JsonObject
  {
  public:
    JsonObject &
    set(const std::string &key, double value);
    JsonObject &
    set(const std::string &key, long long value);
    JsonObject &
    set(const std::string &key, unsigned long value);
    JsonObject &
    set(const std::string &key, unsigned int value);
    JsonObject &
    set(const std::string &key, int value);
    JsonObject &
    set(const std::string &key, bool value);
    JsonObject &
    set(const std::string &key, const std::string &value);
    JsonObject &
    set(const std::string &key, const char *value);
    JsonObject &
    set(const std::string &key, const JsonObject &value);
    /// An array of numbers (null where not finite).
    JsonObject &
    set(const std::string &key, const std::vector<double> &numbers);
    /// An array of objects (written as they are now; for a top-level key).
    JsonObject &
    set(const std::string &key, const std::vector<JsonObject> &array);

    /// The nested object under @p key, created if absent.
    JsonObject &
    object(const std::string &key);

    void
    write(std::ostream &out, unsigned int indent = 0) const;

    /// Write to @p file_name, throwing InputError if it cannot be written.
    void
    write_file(const std::string &file_name) const;

  private:
    void
    set_raw(const std::string &key, const std::string &json_text);

    // Either a rendered scalar or an index into children.
    struct Entry
    {
      std::string key;
      std::string scalar;
      int         child = -1;
    };
    std::vector<Entry>      entries;
    std::vector<JsonObject> children;
  };
} // namespace unilateral
