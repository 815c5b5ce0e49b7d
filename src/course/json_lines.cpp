#include "course/json_lines.h"

#include <cctype>
#include <cstring>

namespace sl {

namespace {

class Scanner {
  public:
    Scanner(const std::string& text, std::map<std::string, int>& out,
            std::map<std::string, std::string>* numbers)
        : t_(text), out_(out), numbers_(numbers) {}

    void value(const std::string& path, int depth) {
        skipSpace();
        if (pos_ >= t_.size() || depth > 512) return;
        out_[path] = line_;
        char c = t_[pos_];
        if (c == '{') {
            ++pos_;
            for (;;) {
                skipSpace();
                if (pos_ >= t_.size() || t_[pos_] == '}') break;
                if (t_[pos_] == ',') {
                    ++pos_;
                    continue;
                }
                std::string key = string();
                skipSpace();
                if (pos_ < t_.size() && t_[pos_] == ':') ++pos_;
                value(path + "/" + escaped(key), depth + 1);
            }
            ++pos_;
        } else if (c == '[') {
            ++pos_;
            int index = 0;
            for (;;) {
                skipSpace();
                if (pos_ >= t_.size() || t_[pos_] == ']') break;
                if (t_[pos_] == ',') {
                    ++pos_;
                    continue;
                }
                value(path + "/" + std::to_string(index++), depth + 1);
            }
            ++pos_;
        } else if (c == '"') {
            string();
        } else {
            std::size_t start = pos_;
            while (pos_ < t_.size() && !std::strchr(",]} \t\r\n", t_[pos_])) ++pos_;
            bool number = c == '-' || std::isdigit(static_cast<unsigned char>(c));
            if (numbers_ && number) (*numbers_)[path] = t_.substr(start, pos_ - start);
        }
    }

  private:
    void skipSpace() {
        while (pos_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[pos_]))) {
            if (t_[pos_] == '\n') ++line_;
            ++pos_;
        }
    }

    // A string's raw text (escapes kept as written: keys in our files are plain).
    std::string string() {
        std::string s;
        if (pos_ >= t_.size() || t_[pos_] != '"') return s;
        ++pos_;
        while (pos_ < t_.size() && t_[pos_] != '"') {
            if (t_[pos_] == '\\' && pos_ + 1 < t_.size()) s += t_[pos_++];
            s += t_[pos_++];
        }
        ++pos_;
        return s;
    }

    // RFC 6901: '~' and '/' inside a key.
    static std::string escaped(const std::string& key) {
        std::string out;
        for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
        return out;
    }

    const std::string& t_;
    std::map<std::string, int>& out_;
    std::map<std::string, std::string>* numbers_;
    std::size_t pos_ = 0;
    int line_ = 1;
};

}  // namespace

std::map<std::string, int> jsonValueLines(const std::string& text,
                                          std::map<std::string, std::string>* numbers) {
    std::map<std::string, int> out;
    Scanner(text, out, numbers).value("", 0);
    return out;
}

}  // namespace sl
