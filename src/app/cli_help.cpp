#include "cli_help.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace collide::app {

namespace {

/// The width of the options' and commands' first column (names and value types).
constexpr std::size_t name_column = 30;
/// The narrowest description column: below it, text goes under the names at full width.
constexpr std::size_t min_description = 24;

/// One line of `text` wrapped to `width`, appended to `out` (no final newline).
void wrap_line(const std::string& line, std::size_t width, std::string& out) {
    std::istringstream words(line);
    std::string word;
    std::size_t used = 0;
    while (words >> word) {
        if (used > 0 && used + 1 + word.size() > width) {
            out += '\n';
            used = 0;
        } else if (used > 0) {
            out += ' ';
            ++used;
        }
        out += word;
        used += word.size();
    }
}

/// CLI11's formatter with every description wrapped: the option and command lists keep their two
/// columns, the description column as wide as the terminal leaves it.
class WrappingFormatter final : public CLI::Formatter {
  public:
    explicit WrappingFormatter(int width) : width_(static_cast<std::size_t>(std::max(width, 40))) {
        column_width(name_column);
    }

    std::string make_option(const CLI::Option* opt, bool is_positional) const override {
        return two_columns(make_option_name(opt, is_positional) + make_option_opts(opt),
                           make_option_desc(opt));
    }
    std::string make_subcommand(const CLI::App* sub) const override {
        return two_columns(sub->get_display_name(true), sub->get_description());
    }
    std::string make_description(const CLI::App* app) const override {
        const std::string text = CLI::Formatter::make_description(app);
        return text.empty() ? text : wrap_text(text, width_) + "\n";
    }
    std::string make_footer(const CLI::App* app) const override {
        const std::string text = CLI::Formatter::make_footer(app);
        return text.empty() ? text : wrap_text(text, width_);
    }
    std::string make_usage(const CLI::App* app, std::string name) const override {
        return wrap_text(CLI::Formatter::make_usage(app, std::move(name)), width_) + "\n";
    }

  private:
    /// "  NAME   description", the description wrapped in its column (under the name, indented,
    /// when the name is wider than its column).
    [[nodiscard]] std::string two_columns(const std::string& name,
                                          const std::string& description) const {
        const std::size_t column = get_column_width();
        const std::size_t room = width_ > column + min_description ? width_ - column : width_ - 8;
        std::ostringstream out;
        CLI::detail::format_help(out, name, wrap_text(description, room), column);
        return out.str();
    }

    std::size_t width_;
};

}  // namespace

std::string wrap_text(const std::string& text, std::size_t width) {
    std::string out;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        if (line.size() <= width) {
            out += line;
        } else if (line.front() == ' ') {
            // An example or a list item too long for the width: wrapped under its own indent.
            const std::size_t indent = line.find_first_not_of(' ');
            std::string wrapped;
            wrap_line(line.substr(indent), width > indent + 20 ? width - indent - 2 : 20, wrapped);
            const std::string pad(indent, ' ');
            out += pad;
            for (const char c : wrapped) out += c == '\n' ? "\n" + pad + "  " : std::string(1, c);
        } else {
            wrap_line(line, width, out);
        }
        if (end == text.size()) break;
        out += '\n';
        start = end + 1;
    }
    return out;
}

void use_wrapping_help(CLI::App& root, int width) {
    root.formatter(std::make_shared<WrappingFormatter>(width));
}

void add_help_command(CLI::App& root) {
    CLI::App* help = root.add_subcommand(
        "help", "Show the help of collide, or of one command: collide help render");
    // Only for the lists: main turns `help X` into `X --help` before parsing.
    help->add_option("command")
        ->description("The command whose help to show")
        ->type_name("COMMAND");
}

void help_as_flag(int& argc, char**& argv, std::vector<char*>& storage) {
    static char help_flag[] = "--help";
    if (argc < 2 || std::strcmp(argv[1], "help") != 0) return;
    storage.assign(argv, argv + argc);
    storage.erase(storage.begin() + 1);
    // `help COMMAND ...`: the command's help; anything after it is ignored, as --help does.
    if (storage.size() > 2) storage.resize(2);
    storage.push_back(help_flag);
    argc = static_cast<int>(storage.size());
    storage.push_back(nullptr);
    argv = storage.data();
}

}  // namespace collide::app
