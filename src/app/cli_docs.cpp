#include "cli_docs.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "collide_build_info.hpp"
#include "commands.hpp"
#include "json_output.hpp"

namespace collide::app {

namespace {

/// "TEXT:{a,b,c}" or "{a,b,c}" -> {"a", "b", "c"}: the choices CLI11's IsMember check describes,
/// or a type name set by hand.
std::vector<std::string> choices_in(const std::string& type_name) {
    const std::size_t open = type_name.find('{');
    const std::size_t close = type_name.find('}', open);
    if (open == std::string::npos || close == std::string::npos) return {};
    std::vector<std::string> choices;
    std::string current;
    for (const char c : type_name.substr(open + 1, close - open - 1)) {
        if (c == ',') {
            choices.push_back(current);
            current.clear();
        } else if (c != ' ') {
            current += c;
        }
    }
    if (!current.empty()) choices.push_back(current);
    return choices;
}

OptionDoc describe_option(const CLI::Option& opt) {
    OptionDoc doc;
    doc.positional = opt.get_positional();
    if (doc.positional) {
        doc.names.push_back(opt.get_name(true));
    } else {
        for (const std::string& s : opt.get_snames()) doc.names.push_back("-" + s);
        for (const std::string& l : opt.get_lnames()) doc.names.push_back("--" + l);
    }
    const std::string type_name = opt.get_type_name();
    // A flag expects no value (CLI11's add_flag sets expected(0)); an option like --queue [K]
    // expects 0 or 1 and shows its value.
    if (opt.get_expected_max() != 0) {
        // IsMember's "TEXT:{a,b}" shows as "TEXT"; a choice may hold a colon itself ("dary:D").
        const std::size_t colon = type_name.find(':');
        doc.value = colon < type_name.find('{') ? type_name.substr(0, colon) : type_name;
        doc.choices = choices_in(type_name);
        if (doc.value.empty()) doc.value = "VALUE";
    }
    doc.description = opt.get_description();
    doc.required = opt.get_required();
    return doc;
}

CommandDoc describe_command(const CLI::App& app) {
    CommandDoc doc;
    doc.name = app.get_parent() == nullptr ? "" : app.get_name();
    doc.description = app.get_description();
    doc.footer = app.get_footer();
    for (const CLI::Option* opt : app.get_options()) {
        if (opt->get_group().empty()) continue;  // hidden
        doc.options.push_back(describe_option(*opt));
    }
    return doc;
}

// ---- roff -------------------------------------------------------------------------------------

/// Text for a roff line: backslashes escaped, a leading dot or quote made literal, dashes as
/// minus signs (every dash in this text is an option's or a command line's).
std::string roff(std::string_view text) {
    std::string out;
    for (const char c : text) {
        if (c == '\\') {
            out += "\\e";
        } else if (c == '-') {
            out += "\\-";
        } else {
            out += c;
        }
    }
    return out;
}

/// A paragraph of roff: each line of `text` made safe at its start.
std::string roff_lines(std::string_view text) {
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string line = roff(text.substr(start, end - start));
        if (!line.empty() && (line.front() == '.' || line.front() == '\'')) out += "\\&";
        out += line.empty() ? ".sp" : line;
        out += '\n';
        start = end + 1;
    }
    return out;
}

std::string option_heading(const OptionDoc& o) {
    std::string out;
    for (const std::string& name : o.names) {
        if (!out.empty()) out += ", ";
        out += (o.positional ? "\\fI" : "\\fB") + roff(name) + "\\fR";
    }
    if (!o.value.empty() && !o.positional) out += " \\fI" + roff(o.value) + "\\fR";
    return out;
}

std::string usage_of(const CommandDoc& c) {
    std::string usage = "collide " + c.name;
    if (std::any_of(c.options.begin(), c.options.end(),
                    [](const OptionDoc& o) { return !o.positional; }))
        usage += " [OPTIONS]";
    for (const OptionDoc& o : c.options) {
        if (!o.positional) continue;
        std::string name = o.names.front();
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
        usage += o.required ? " " + name : " [" + name + "]";
    }
    return usage;
}

std::string man_options(const std::vector<OptionDoc>& options) {
    std::string out;
    for (const OptionDoc& o : options) {
        out += ".TP\n" + option_heading(o) + "\n";
        std::string text = o.description;
        if (!o.choices.empty()) {
            std::string list;
            for (const std::string& choice : o.choices) list += (list.empty() ? "" : ", ") + choice;
            text += " (one of: " + list + ")";
        }
        out += roff_lines(text.empty() ? "(no description)" : text);
    }
    return out;
}

// ---- shells ----------------------------------------------------------------------------------

/// The choices a shell offers to complete: each as it may be typed ("indexed[:D]" -> "indexed");
/// a choice with a value to fill in ("dary:D") is left to the user.
std::vector<std::string> completion_words(const OptionDoc& o) {
    std::vector<std::string> words;
    for (const std::string& choice : o.choices) {
        const std::string word = choice.substr(0, choice.find('['));
        if (word.find(':') == std::string::npos) words.push_back(word);
    }
    return words;
}

std::string joined(const std::vector<std::string>& words, std::string_view separator) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : std::string(separator)) + w;
    return out;
}

/// The first sentence of a description, without the characters the shells' quoting and zsh's
/// _arguments specs treat specially, at most 70 characters.
std::string short_text(const std::string& description) {
    std::string out;
    for (const char c : description) {
        if (c == '\n') break;
        if (c == '\'' || c == '"' || c == '\\' || c == '[' || c == ']' || c == ':' || c == '`' ||
            c == '$')
            continue;
        out += c;
    }
    if (const std::size_t stop = out.find(". "); stop != std::string::npos) out.resize(stop);
    if (out.size() > 70) {
        out.resize(70);
        if (const std::size_t space = out.rfind(' '); space != std::string::npos && space > 40)
            out.resize(space);
        out += "...";
    }
    return out;
}

std::vector<const CommandDoc*> subcommands(const std::vector<CommandDoc>& commands) {
    std::vector<const CommandDoc*> out;
    for (const CommandDoc& c : commands) {
        if (!c.name.empty()) out.push_back(&c);
    }
    return out;
}

std::vector<std::string> option_names(const CommandDoc& c) {
    std::vector<std::string> names;
    for (const OptionDoc& o : c.options) {
        if (!o.positional) names.insert(names.end(), o.names.begin(), o.names.end());
    }
    return names;
}

bool has_positional(const CommandDoc& c) {
    return std::any_of(c.options.begin(), c.options.end(),
                       [](const OptionDoc& o) { return o.positional; });
}

}  // namespace

bool OptionDoc::takes_path() const {
    static constexpr std::string_view path_types[] = {"PATH", "FILE", "DIR", "SCENE"};
    return std::find(std::begin(path_types), std::end(path_types), value) != std::end(path_types);
}

std::vector<CommandDoc> describe_commands(const CLI::App& root) {
    std::vector<CommandDoc> commands{describe_command(root)};
    for (const CLI::App* sub : root.get_subcommands([](const CLI::App*) { return true; })) {
        if (sub->get_name().empty() || sub->get_group().empty()) continue;
        commands.push_back(describe_command(*sub));
    }
    return commands;
}

std::string man_page(const std::vector<CommandDoc>& commands) {
    const CommandDoc& root = commands.front();
    std::string out;
    out += ".\\\" The man page of collide, generated from its command line (collide-draw\n";
    out +=
        ".\\\" --generate-docs man) when the program is built: edit the program, not this file.\n";
    out +=
        ".TH COLLIDE 1 \"\" \"collide " + std::string(COLLIDE_VERSION) + "\" \"User Commands\"\n";
    out += ".SH NAME\ncollide \\- teaching videos of event\\-driven hard\\-disc simulation\n";
    out += ".SH SYNOPSIS\n.B collide\n.RI [ OPTIONS ]\n.I COMMAND\n.RI [ ARGUMENTS ]\n";
    out += ".br\n.B collide help\n.RI [ COMMAND ]\n";
    out += ".SH DESCRIPTION\n" + roff_lines(root.description);
    out +=
        ".PP\n"
        "Every command checks its input first: bad input gets one message naming the file, "
        "line and field, and exit status 2, before any output is created. Outputs appear whole "
        "or not at all.\n";
    out += ".SH OPTIONS\n" + man_options(root.options);
    out += ".SH COMMANDS\n";
    for (const CommandDoc* c : subcommands(commands)) {
        out += ".SS \"" + roff(usage_of(*c)) + "\"\n";
        out += roff_lines(c->description);
        out += man_options(c->options);
        if (!c->footer.empty()) out += ".PP\n.nf\n" + roff_lines(c->footer) + ".fi\n";
    }
    out +=
        ".SH EXIT STATUS\n"
        ".TP\n.B 0\nSuccess (for \\fBcompare\\fR: the images match).\n"
        ".TP\n.B 1\nA failure while running: a file that cannot be written, an encoder error, "
        "memory exhausted; for \\fBcompare\\fR: the images differ.\n"
        ".TP\n.B 2\nBad input or usage: a scene, an option or a path, named in the message.\n"
        ".TP\n.B 128+N\nStopped by signal N (130 for Ctrl\\-C) after a clean stop: nothing half "
        "written is left.\n";
    out +=
        ".SH ENVIRONMENT\n"
        ".TP\n.B COLLIDE_DATA_DIR\nThe data directory (the one holding \\fIscenes/\\fR), "
        "instead of the one beside the program; \\fBCOLLIDE_ASSETS_DIR\\fR is its older name.\n"
        ".TP\n.B COLLIDE_FONT\nThe TrueType font for text when \\fB\\-\\-font\\fR is not "
        "given; otherwise DejaVu Sans, then what \\fBfc\\-match\\fR(1) names.\n"
        ".TP\n.B COLUMNS\nThe width of help and progress lines when the output is not a "
        "terminal (default 80).\n";
    out +=
        ".SH FILES\n"
        ".TP\n.I /usr/share/collide/scenes/\n"
        "The built\\-in scenes (\\fBcollide scenes\\fR lists them), found beside the program "
        "as \\fI../share/collide\\fR, so an installed tree can be moved.\n"
        ".TP\n.I /usr/libexec/collide/collide\\-draw\n"
        "The drawing half (OpenGL, video encoders), which \\fBcollide\\fR runs for render, "
        "thumbnail, heap and a puzzle video.\n";
    out += ".SH SEE ALSO\n.BR ffmpeg (1),\n.BR ffprobe (1),\n.BR fc\\-match (1)\n";
    return out;
}

std::string bash_completion(const std::vector<CommandDoc>& commands) {
    std::vector<std::string> names;
    for (const CommandDoc* c : subcommands(commands)) names.push_back(c->name);
    std::string out =
        "# bash completion for collide, generated from its command line (collide-draw\n"
        "# --generate-docs bash): plain bash, no bash-completion functions needed.\n"
        "_collide() {\n"
        "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
        "    local command='' i options='' files=1\n"
        "    local commands='" +
        joined(names, " ") +
        "'\n"
        "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
        "        case ${COMP_WORDS[i]} in -*) ;; *) command=${COMP_WORDS[i]}; break ;; esac\n"
        "    done\n"
        "    case $command in\n";
    for (const CommandDoc& c : commands) {
        out += "        " + (c.name.empty() ? std::string("''") : c.name) + ") options='" +
               joined(option_names(c), " ") + "'";
        if (c.name.empty()) out += "; files=0";
        out += " ;;\n";
    }
    out +=
        "    esac\n"
        "    # The value of the option before the cursor.\n"
        "    case \"$command $prev\" in\n";
    for (const CommandDoc* c : subcommands(commands)) {
        for (const OptionDoc& o : c->options) {
            if (o.positional || o.value.empty()) continue;
            std::vector<std::string> patterns;
            for (const std::string& n : o.names) patterns.push_back("'" + c->name + " " + n + "'");
            out += "        " + joined(patterns, "|") + ")\n";
            if (!o.choices.empty()) {
                out += "            COMPREPLY=($(compgen -W '" + joined(completion_words(o), " ") +
                       "' -- \"$cur\")); return ;;\n";
            } else if (o.takes_path()) {
                out += "            COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n";
            } else {
                out += "            COMPREPLY=(); return ;;  # " + o.value + "\n";
            }
        }
    }
    out +=
        "    esac\n"
        "    if [[ $cur == -* ]]; then\n"
        "        COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))\n"
        "    elif [[ -z $command ]]; then\n"
        "        COMPREPLY=($(compgen -W \"$commands\" -- \"$cur\"))\n"
        "    elif ((files)); then\n"
        "        COMPREPLY=($(compgen -f -- \"$cur\"))\n"
        "    fi\n"
        "}\n"
        "complete -o filenames -F _collide collide\n";
    return out;
}

std::string zsh_completion(const std::vector<CommandDoc>& commands) {
    const auto specs = [](const CommandDoc& c, const std::string& indent) {
        std::string out;
        for (const OptionDoc& o : c.options) {
            if (o.positional) {
                out += indent + "'" + std::string(o.required ? "" : ":") + ":" + o.names.front() +
                       ":_files' \\\n";
                continue;
            }
            std::string action;
            if (!o.value.empty()) {
                // _arguments ends the message at a colon: a choice's own ("dary:D") is escaped.
                std::string message;
                for (const char ch : o.value)
                    message += ch == ':' ? std::string("\\:") : std::string(1, ch);
                action = ":" + message + ":";
                if (!o.choices.empty()) {
                    action += "(" + joined(completion_words(o), " ") + ")";
                } else if (o.takes_path()) {
                    action += "_files";
                }
            }
            const std::string exclusive =
                o.names.size() > 1 ? "(" + joined(o.names, " ") + ")" : std::string();
            for (const std::string& name : o.names) {
                out += indent + "'" + exclusive + name + "[" + short_text(o.description) + "]" +
                       action + "' \\\n";
            }
        }
        return out;
    };
    std::string out =
        "#compdef collide\n"
        "# zsh completion for collide, generated from its command line (collide-draw\n"
        "# --generate-docs zsh).\n"
        "_collide() {\n"
        "    local curcontext=$curcontext state line ret=1\n"
        "    _arguments -C \\\n";
    out += specs(commands.front(), "        ");
    out +=
        "        '1:command:->command' \\\n"
        "        '*::argument:->argument' && ret=0\n"
        "    case $state in\n"
        "    command)\n"
        "        local -a commands=(\n";
    for (const CommandDoc* c : subcommands(commands)) {
        out += "            '" + c->name + ":" + short_text(c->description) + "'\n";
    }
    out +=
        "        )\n"
        "        _describe -t commands 'collide command' commands && ret=0 ;;\n"
        "    argument)\n"
        "        case $line[1] in\n";
    for (const CommandDoc* c : subcommands(commands)) {
        out += "        (" + c->name + ")\n            _arguments \\\n";
        out += specs(*c, "                ");
        out += "                && ret=0 ;;\n";
    }
    out +=
        "        esac ;;\n"
        "    esac\n"
        "    return ret\n"
        "}\n"
        "_collide \"$@\"\n";
    return out;
}

std::string fish_completion(const std::vector<CommandDoc>& commands) {
    std::string out =
        "# fish completion for collide, generated from its command line (collide-draw\n"
        "# --generate-docs fish).\n"
        "complete -c collide -f\n";
    const auto option_line = [](const std::string& condition, const OptionDoc& o) {
        std::string line = "complete -c collide -n '" + condition + "'";
        for (const std::string& name : o.names) {
            line += name.size() == 2 ? " -s " + name.substr(1) : " -l " + name.substr(2);
        }
        if (!o.value.empty()) {
            if (!o.choices.empty()) {
                line += " -x -a '" + joined(completion_words(o), " ") + "'";
            } else if (o.takes_path()) {
                line += " -r -F";
            } else {
                line += " -x";
            }
        }
        return line + " -d '" + short_text(o.description) + "'\n";
    };
    for (const OptionDoc& o : commands.front().options) {
        if (!o.positional) out += option_line("__fish_use_subcommand", o);
    }
    for (const CommandDoc* c : subcommands(commands)) {
        out += "complete -c collide -n __fish_use_subcommand -a " + c->name + " -d '" +
               short_text(c->description) + "'\n";
    }
    for (const CommandDoc* c : subcommands(commands)) {
        const std::string condition = "__fish_seen_subcommand_from " + c->name;
        for (const OptionDoc& o : c->options) {
            if (!o.positional) out += option_line(condition, o);
        }
        if (has_positional(*c)) out += "complete -c collide -n '" + condition + "' -F\n";
    }
    return out;
}

std::string commands_json(const std::vector<CommandDoc>& commands) {
    Json list = Json::array();
    for (const CommandDoc& c : commands) {
        Json options = Json::array();
        for (const OptionDoc& o : c.options) {
            options.push_back(Json{{"names", o.names},
                                   {"value", o.value},
                                   {"choices", o.choices},
                                   {"positional", o.positional}});
        }
        list.push_back(Json{{"name", c.name}, {"options", options}});
    }
    return json_text(Json{{"commands", list}});
}

void add_docs_generator(CLI::App& root) {
    root.add_option_function<std::string>(
            "--generate-docs",
            [&root](const std::string& kind) {
                const std::vector<CommandDoc> commands = describe_commands(root);
                std::string text;
                if (kind == "man") text = man_page(commands);
                if (kind == "bash") text = bash_completion(commands);
                if (kind == "zsh") text = zsh_completion(commands);
                if (kind == "fish") text = fish_completion(commands);
                if (kind == "json") text = commands_json(commands);
                std::fputs(text.c_str(), stdout);
                if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) throw ExitStatus{1};
                throw ExitStatus{0};
            },
            "")
        ->check(CLI::IsMember({"man", "bash", "zsh", "fish", "json"}))
        ->group("");  // for the build, not for users: hidden from --help and the documents
}

}  // namespace collide::app
