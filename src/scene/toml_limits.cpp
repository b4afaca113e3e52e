// A lexical pass over a TOML scene before it is parsed (toml_limits.hpp): strings and comments
// are skipped, brackets and dotted-key parts counted, with an explicit stack (no recursion).

#include "toml_limits.hpp"

#include <vector>

#include "collide/error.hpp"

namespace collide {

namespace {

class Scanner {
  public:
    Scanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    void run() {
        while (i_ < text_.size()) {
            const char c = text_[i_];
            if (c == '\n') {
                ++line_;
                ++i_;
                if (open_.empty()) expect_key_ = true;  // the next top-level line starts anew
                continue;
            }
            if (c == ' ' || c == '\t' || c == '\r') {
                ++i_;
                continue;
            }
            if (c == '#') {
                skip_comment();
                continue;
            }
            if (expect_key_ && open_.empty() && c == '[') {
                header();
                continue;
            }
            if (expect_key_) {
                key();
                continue;
            }
            value_char(c);
        }
    }

  private:
    struct Open {
        bool inline_table;
        std::size_t depth;  ///< what this level adds: its key's parts, plus one for itself
    };

    [[noreturn]] void too_deep() const {
        throw_scene_error(file_, line_, "",
                          "nested too deeply: at most " + std::to_string(max_toml_depth) +
                              " levels of tables, dotted-key parts, arrays and inline tables "
                              "(docs/scenes.md, \"Limits\")");
    }

    void count_value() {
        if (++values_ > max_toml_values) {
            throw_scene_error(file_, line_, "",
                              "more than " + std::to_string(max_toml_values) +
                                  " values in one TOML scene; give many discs as an algs4 file "
                                  "or a [[generate]] block (docs/scenes.md, \"Limits\")");
        }
    }

    void check_depth(std::size_t extra) const {
        if (header_depth_ + open_depth_ + extra > max_toml_depth) too_deep();
    }

    void skip_comment() {
        while (i_ < text_.size() && text_[i_] != '\n') ++i_;
    }

    bool starts_with(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

    // Skips the string starting at i_ (any of the four kinds), counting its newlines.
    void skip_string() {
        const char quote = text_[i_];
        const std::string_view triple = quote == '"' ? "\"\"\"" : "'''";
        if (starts_with(triple)) {
            i_ += 3;
            while (i_ < text_.size() && !starts_with(triple)) {
                if (text_[i_] == '\n') ++line_;
                if (quote == '"' && text_[i_] == '\\') ++i_;  // an escaped character
                ++i_;
            }
            i_ += 3;
            // A closing delimiter may be preceded by up to two quotes of the content.
            for (int extra = 0; extra < 2 && i_ < text_.size() && text_[i_] == quote; ++extra) ++i_;
            return;
        }
        ++i_;
        while (i_ < text_.size() && text_[i_] != quote && text_[i_] != '\n') {
            if (quote == '"' && text_[i_] == '\\') ++i_;
            ++i_;
        }
        if (i_ < text_.size() && text_[i_] == quote) ++i_;
    }

    // A key up to its '=' (or the end of the line): the number of its dotted parts.
    std::size_t key_parts(char stop) {
        std::size_t parts = 1;
        while (i_ < text_.size() && text_[i_] != stop && text_[i_] != '\n') {
            const char c = text_[i_];
            if (c == '"' || c == '\'') {
                skip_string();
                continue;
            }
            if (c == '#') return parts;
            if (c == '}' && stop == '=') return parts;  // an empty inline table: no key at all
            if (c == '.') {
                ++parts;
                if (header_depth_ + open_depth_ + parts > max_toml_depth) too_deep();
            }
            ++i_;
        }
        return parts;
    }

    // [a.b.c] or [[a.b.c]] at the start of a top-level line.
    void header() {
        ++i_;
        if (i_ < text_.size() && text_[i_] == '[') ++i_;
        header_depth_ = 0;
        header_depth_ = key_parts(']');
        count_value();
        while (i_ < text_.size() && text_[i_] == ']') ++i_;
        expect_key_ = false;  // the rest of the line is a comment or a syntax error
    }

    void key() {
        const char c = text_[i_];
        if (c == '}' || c == ',') {  // `{}` or a stray comma: leave it to the value rules
            expect_key_ = false;
            return;
        }
        pending_key_ = key_parts('=');
        check_depth(pending_key_);
        count_value();
        if (i_ < text_.size() && text_[i_] == '=') ++i_;
        expect_key_ = false;
    }

    void value_char(char c) {
        switch (c) {
            case '"':
            case '\'':
                skip_string();
                return;
            case '[':
            case '{': {
                const std::size_t depth = pending_key_ + 1;
                check_depth(depth);
                open_.push_back({c == '{', depth});
                open_depth_ += depth;
                pending_key_ = 0;
                count_value();
                expect_key_ = c == '{';
                break;
            }
            case ']':
            case '}':
                if (!open_.empty()) {
                    open_depth_ -= open_.back().depth;
                    open_.pop_back();
                }
                break;
            case ',':
                count_value();
                if (!open_.empty() && open_.back().inline_table) expect_key_ = true;
                break;
            default:
                break;
        }
        ++i_;
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t i_ = 0;
    int line_ = 1;
    bool expect_key_ = true;
    std::size_t header_depth_ = 0;  ///< parts of the current [table] header
    std::size_t pending_key_ = 0;   ///< parts of the key whose value comes next
    std::vector<Open> open_;        ///< the arrays and inline tables open here
    std::size_t open_depth_ = 0;    ///< the sum of open_'s depths
    std::size_t values_ = 0;
};

}  // namespace

void check_toml_limits(std::string_view text, const std::string& file) {
    Scanner(text, file).run();
}

}  // namespace collide
