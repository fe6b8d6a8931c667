// Command-line errors with suggestions (see cli_errors.hpp).
#include "app/cli_errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "scene/scene_schema.hpp"

namespace ffrf::app {
namespace {

bool starts_with(const std::string& text, std::string_view prefix) { return text.rfind(prefix, 0) == 0; }

// An option token ("--out", "--out=x", "-N", "-N64"); negative numbers are values.
bool is_option(const std::string& token) {
  if (starts_with(token, "--")) return token.size() > 2;
  return token.size() > 1 && token[0] == '-' && std::isalpha(static_cast<unsigned char>(token[1]));
}

// "--out=x" -> "--out", "-N64" -> "-N".
std::string option_name(const std::string& token) {
  if (starts_with(token, "--")) return token.substr(0, token.find('='));
  return token.substr(0, 2);
}

// The keywords an option takes, from the "a|b|c" list in its description ("rigid|nodal|modal").
std::vector<std::string> choices_of(const CLI::Option& option) {
  std::vector<std::string> choices;
  const std::string description = option.get_description();
  std::string word;
  const auto flush = [&] {
    if (word.find('|') != std::string::npos) {
      std::size_t start = 0;
      for (std::size_t bar = word.find('|'); ; bar = word.find('|', start)) {
        choices.push_back(word.substr(start, bar == std::string::npos ? std::string::npos : bar - start));
        if (bar == std::string::npos) break;
        start = bar + 1;
      }
    }
    word.clear();
  };
  for (const char c : description) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '|' || c == '-' || c == '_') {
      word += c;
    } else {
      flush();
    }
  }
  flush();
  return choices;
}

std::vector<std::string> long_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

// "did you mean --boom modal?" for an unknown option (value: the token after it, if any).
std::string suggestion(const CLI::App& command, const std::string& unknown, const std::string& value) {
  std::vector<std::string> hints;
  if (!value.empty()) {
    for (const CLI::Option* option : command.get_options()) {
      const auto choices = choices_of(*option);
      if (!option->get_lnames().empty() && std::find(choices.begin(), choices.end(), value) != choices.end()) {
        hints.push_back(fmt::format("--{} {}", option->get_lnames().front(), value));
      }
    }
  }
  const std::string wanted = unknown.substr(unknown.find_first_not_of('-'));
  std::string closest;
  std::size_t best = std::max<std::size_t>(2, wanted.size() / 3) + 1;
  for (const std::string& name : long_names(command)) {
    const std::size_t distance = scene::edit_distance(wanted, name.substr(2));
    if (distance < best) {
      best = distance;
      closest = name;
    }
  }
  if (!closest.empty() && std::none_of(hints.begin(), hints.end(), [&](const std::string& h) { return starts_with(h, closest + " "); })) {
    hints.push_back(closest);
  }
  if (hints.empty()) return fmt::format("; `ffrf {} --help` lists the options", command.get_name());
  std::string text = "; did you mean " + hints.front();
  for (std::size_t i = 1; i < hints.size(); ++i) text += " or " + hints[i];
  return text + "?";
}

const CLI::App* find_command(const CLI::App& app, const std::string& name) {
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->get_name() == name) return command;
  }
  return nullptr;
}

// The first option of `command` among `arguments` (from `first`) that it does not know, with the
// message naming it; nothing when every option is known.
std::optional<std::string> unknown_option(const CLI::App& app, const CLI::App& command,
                                          const std::vector<std::string>& arguments, std::size_t first) {
  for (std::size_t i = first; i < arguments.size(); ++i) {
    const std::string& token = arguments[i];
    if (token == "--") break;
    if (!is_option(token)) continue;
    const std::string name = option_name(token);
    if (command.get_option_no_throw(name) != nullptr || app.get_option_no_throw(name) != nullptr) continue;
    std::string value;
    if (const auto equals = token.find('='); equals != std::string::npos) {
      value = token.substr(equals + 1);
    } else if (i + 1 < arguments.size() && !is_option(arguments[i + 1])) {
      value = arguments[i + 1];
    }
    return fmt::format("{}: unknown option of `ffrf {}`{}", name, command.get_name(), suggestion(command, name, value));
  }
  return std::nullopt;
}

std::string command_names(const CLI::App& app) {
  std::string names;
  for (const CLI::App* command : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + command->get_name();
  return names;
}

}  // namespace

CommandLineError explain_parse_error(const CLI::App& app, const CLI::ParseError& error,
                                     const std::vector<std::string>& arguments) {
  // The command: the first argument that is not an option.
  std::size_t position = 0;
  while (position < arguments.size() && is_option(arguments[position])) ++position;
  if (position == arguments.size()) {
    if (position > 0 && app.get_option_no_throw(option_name(arguments.front())) == nullptr) {
      return {"", fmt::format("{}: unknown option; give a command first ({})", option_name(arguments.front()),
                              command_names(app))};
    }
    return {"", fmt::format("give a command: {} (`ffrf --help` says what each does)", command_names(app))};
  }
  const CLI::App* command = find_command(app, arguments[position]);
  if (command == nullptr) {
    std::string closest;
    std::size_t best = 3;
    for (const CLI::App* candidate : app.get_subcommands({})) {
      const std::size_t distance = scene::edit_distance(arguments[position], candidate->get_name());
      if (distance < best) {
        best = distance;
        closest = candidate->get_name();
      }
    }
    return {"", fmt::format("{}: unknown command{} (the commands are {})", arguments[position],
                            closest.empty() ? "" : "; did you mean " + closest + "?", command_names(app))};
  }
  if (const auto unknown = unknown_option(app, *command, arguments, position + 1)) return {command->get_name(), *unknown};
  std::string message = error.what();
  if (dynamic_cast<const CLI::ValidationError*>(&error) != nullptr) {
    // "--elements: 3000000000: out of range ..." -> "--elements 3000000000: out of range ..."
    if (const auto colon = message.find(": "); colon != std::string::npos) message.replace(colon, 2, " ");
  } else if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
    message += fmt::format(" (`ffrf {} --help` lists the arguments)", command->get_name());
  } else if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr) {
    message = fmt::format("missing argument: {} (`ffrf {} --help` shows the usage)", message, command->get_name());
  } else if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    message += " (a value must follow the option)";
  }
  return {command->get_name(), message};
}

std::optional<std::string> empty_value(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0) continue;
    for (const std::string& result : option->results()) {
      if (!result.empty()) continue;
      const std::string name = option->get_lnames().empty() ? option->get_name(true) : "--" + option->get_lnames().front();
      return fmt::format("{} \"\": an empty value; give {}", name,
                         name == "--out" ? "a directory" : (name == "scene" ? "the scene file" : "a value"));
    }
  }
  return std::nullopt;
}

}  // namespace ffrf::app
