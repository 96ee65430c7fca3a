// impetus: the command-line tool. `impetus calc` evaluates any model of the library,
// `impetus demo` runs a headless demo, `impetus run` simulates a scene file.
#include "calc/calc.hpp"
#include "demos/demos.hpp"
#include "numbers.hpp"
#include "run_command.hpp"

#include <impetus/error.hpp>
#include <impetus/version.hpp>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <exception>
#include <iterator>
#include <string_view>

namespace {

/// The subcommands, as `impetus --help` lists them.
constexpr std::string_view commands[] = {"calc", "demo", "run"};

/// Whether the first word is a command the tool has (options such as --help pass).
bool knownCommand(std::string_view word) {
  return word.empty() || word.front() == '-' ||
         std::find(std::begin(commands), std::end(commands), word) != std::end(commands);
}

int run(int argc, char** argv);

} // namespace

int main(int argc, char** argv) {
  // Whatever a command throws ends in one line on stderr and exit status 2, never an abort.
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
}

namespace {

int run(int argc, char** argv) {
  if (argc > 1 && !knownCommand(argv[1])) {
    fmt::print(stderr, "error: unknown command '{}' (the commands: calc, demo, run; impetus --help)\n", argv[1]);
    return 2;
  }
  CLI::App app{"Impetus: game physics from Physics for Game Developers (2nd ed.), as a modern library", "impetus"};
  app.set_version_flag("--version", std::string("impetus ") + impetus::versionString);
  app.require_subcommand(1);

  auto* calc = app.add_subcommand("calc", "evaluate a model: impetus calc MODEL --param value ... [--json]");
  bool list = false;
  bool json = false;
  std::string model;
  // `impetus calc MODEL --help` is the model's own help (its parameters, runCalc): the model name
  // ends calc's options, so calc's --help is only the one before it.
  calc->set_help_flag();
  bool calcHelp = false;
  calc->add_flag("-h,--help", calcHelp, "this help (impetus calc MODEL --help: the model's parameters)");
  calc->add_flag("--list", list, "list every model with its parameters and units");
  calc->add_flag("--json", json, "machine-readable output");
  calc->add_option("model", model, "model name (see --list)");
  // Everything after the model name is the model's own --param value list.
  calc->prefix_command();

  auto* demo = app.add_subcommand("demo", "run a demo headless and print what it shows");
  std::string demoName;
  bool demoList = false;
  demo->add_option("name", demoName, "demo name (default: the flagship demo)");
  demo->add_flag("--list", demoList, "list the demos");
  std::string demoOut;
  demo->add_option("--out", demoOut,
                   "directory to write the demo's CSV files to (doppler: a .wav file or a directory)");
  std::string demoSpeed;
  std::string demoFrequency;
  auto* demoSpeedOption = demo->add_option("--speed", demoSpeed, "doppler: the source's speed, m/s (default 30)");
  auto* demoFrequencyOption =
      demo->add_option("--frequency", demoFrequency, "doppler: the source's frequency, Hz (default 440)");

  auto* run = app.add_subcommand(
      "run", "simulate a scene file (particles or rigid2d): impetus run SCENE.json --steps N [--dt H] [--out FILE] "
             "[--every K] [--events FILE.csv] [--threads T] [--hash]");
  impetus::cli::RunOptions runOptions;
  run->add_option("scene", runOptions.scene, "scene file (JSON, docs/scene-format.md, docs/scene-format-2d.md)")
      ->required();
  // Numbers are read as text and converted by the tool (numbers.hpp), so that every refusal has
  // the one form "--option = text: reason".
  std::string steps;
  std::string dt;
  std::string every;
  std::string threads;
  run->add_option("--steps", steps, "number of steps to take")->required();
  run->add_option("--dt", dt, "time step, s (default 1/60)");
  run->add_option("--out", runOptions.out, "trajectory file: .csv or .json");
  run->add_option("--every", every, "record every K-th step (default 1)");
  run->add_option("--events", runOptions.events, "rigid2d scenes: contact and joint events, .csv");
  run->add_option("--threads", threads,
                  "rigid2d scenes: threads stepping the world (results are bit-identical at any count)");
  run->add_flag("--hash", runOptions.hash, "print the final state's hash (identical states, identical hashes)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors exit with 2, one line on stderr.
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }

  if (calc->parsed()) {
    if (calcHelp && model.empty() && !list) {
      fmt::print("{}", calc->help());
      return 0;
    }
    std::vector<std::string> parameters = calc->remaining();
    if (calcHelp) {
      parameters.emplace_back("--help"); // after the model's name: the model's own help
    }
    return impetus::cli::runCalc(list, json, model, parameters);
  }
  if (demo->parsed()) {
    impetus::cli::DemoOptions options;
    if (!demoOut.empty()) {
      options.outDir = demoOut;
    }
    try {
      if (demoSpeedOption->count() > 0) {
        options.speed = impetus::cli::parseNumber("--speed", demoSpeed);
      }
      if (demoFrequencyOption->count() > 0) {
        options.frequency = impetus::cli::parseNumber("--frequency", demoFrequency);
      }
    } catch (const impetus::Error& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 2;
    }
    return impetus::cli::runDemo(demoName, demoList, options);
  }
  if (run->parsed()) {
    try {
      runOptions.steps = impetus::cli::parseWholeNumber("--steps", steps, 1, impetus::cli::maxSteps);
      if (!dt.empty()) {
        runOptions.dt = impetus::cli::parseNumber("--dt", dt);
      }
      if (!every.empty()) {
        runOptions.every = impetus::cli::parseWholeNumber("--every", every, 1, impetus::cli::maxSteps);
      }
      if (!threads.empty()) {
        runOptions.threads = static_cast<int>(impetus::cli::parseWholeNumber("--threads", threads, 1, 64));
      }
    } catch (const impetus::Error& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 2;
    }
    return impetus::cli::runScene(runOptions);
  }
  return 2;
}

} // namespace
