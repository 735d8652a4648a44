#include <unilateral/base/input_error.h>
#include <unilateral/base/json_writer.h>
#include <unilateral/base/output_file.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace unilateral
{
  namespace
  {
    std::string
    quoted(const std::string &text)
    {
      std::string result = "\"";
      for (const char c : text)
        switch (c)
          {
            case '"':
              result += "\\\"";
              break;
            case '\\':
              result += "\\\\";
              break;
            case '\n':
              result += "\\n";
              break;
            case '\t':
              result += "\\t";
              break;
            default:
              // Every other control character as \u00XX: JSON allows
              // none raw (a run name or a message may hold one).
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char code[7];
                  std::snprintf(code,
                                sizeof(code),
                                "\\u%04x",
                                static_cast<unsigned int>(c));
                  result += code;
                }
              else
                result += c;
          }
      return result + "\"";
    }
  } // namespace

  void
  JsonObject::set_raw(const std::string &key, const std::string &json_text)
  {
    for (auto &entry : entries)
      if (entry.key == key)
        {
          entry.scalar = json_text;
          entry.child  = -1;
          return;
        }
    entries.push_back({key, json_text, -1});
  }

  JsonObject &
  JsonObject::set(const std::string &key, const std::vector<double> &numbers)
  {
    std::ostringstream text;
    text << std::setprecision(17) << "[";
    for (std::size_t k = 0; k < numbers.size(); ++k)
      {
        text << (k > 0 ? ", " : "");
        if (std::isfinite(numbers[k]))
          text << numbers[k];
        else
          text << "null";
      }
    text << "]";
    set_raw(key, text.str());
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const double value)
  {
    // JSON has no NaN or infinity: write null so readers fail loudly on use.
    if (!std::isfinite(value))
      set_raw(key, "null");
    else
      {
        std::ostringstream text;
        text << std::setprecision(17) << value;
        set_raw(key, text.str());
      }
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const long long value)
  {
    set_raw(key, std::to_string(value));
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const unsigned long value)
  {
    set_raw(key, std::to_string(value));
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const unsigned int value)
  {
    set_raw(key, std::to_string(value));
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const int value)
  {
    set_raw(key, std::to_string(value));
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const bool value)
  {
    set_raw(key, value ? "true" : "false");
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const std::string &value)
  {
    set_raw(key, quoted(value));
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const char *value)
  {
    return set(key, std::string(value));
  }

  JsonObject &
  JsonObject::set(const std::string &key, const JsonObject &value)
  {
    object(key) = value;
    return *this;
  }

  JsonObject &
  JsonObject::set(const std::string &key, const std::vector<JsonObject> &array)
  {
    std::ostringstream text;
    text << "[";
    for (std::size_t i = 0; i < array.size(); ++i)
      {
        text << (i == 0 ? "\n    " : ",\n    ");
        array[i].write(text, 4);
      }
    text << (array.empty() ? "]" : "\n  ]");
    set_raw(key, text.str());
    return *this;
  }

  JsonObject &
  JsonObject::object(const std::string &key)
  {
    for (auto &entry : entries)
      if (entry.key == key)
        {
          if (entry.child < 0)
            {
              entry.child = static_cast<int>(children.size());
              children.emplace_back();
            }
          return children[entry.child];
        }
    entries.push_back({key, "", static_cast<int>(children.size())});
    children.emplace_back();
    return children.back();
  }

  void
  JsonObject::write(std::ostream &out, const unsigned int indent) const
  {
    const std::string pad(indent + 2, ' ');
    out << "{";
    for (std::size_t i = 0; i < entries.size(); ++i)
      {
        out << (i == 0 ? "\n" : ",\n") << pad << quoted(entries[i].key) << ": ";
        if (entries[i].child >= 0)
          children[entries[i].child].write(out, indent + 2);
        else
          out << entries[i].scalar;
      }
    out << "\n" << std::string(indent, ' ') << "}";
  }

  void
  JsonObject::write_file(const std::string &file_name) const
  {
    std::ofstream out = open_for_writing(file_name);
    write(out);
    out << "\n";
    finish_writing(out, file_name);
  }
} // namespace unilateral
