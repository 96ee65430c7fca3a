// impetus: the command-line tool. `impetus calc` evaluates any model of the library,
// `impetus demo` runs a headless demo, `impetus run` simulates a scene file.
#include "calc/calc.hpp"
#include "demos/demos.hpp"
#include "run_command.hpp"

#include <impetus/version.hpp>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

int main(int argc, char** argv) {
  CLI::App app{"Impetus: game physics from Physics for Game Developers (2nd ed.), as a modern library", "impetus"};
  app.set_version_flag("--version", std::string("impetus ") + impetus::versionString);
  app.require_subcommand(1);

  auto* calc = app.add_subcommand("calc", "evaluate a model: impetus calc MODEL --param value ... [--json]");
  bool list = false;
  bool json = false;
  std::string model;
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
  double demoSpeed = 0.0;
  double demoFrequency = 0.0;
  auto* demoSpeedOption = demo->add_option("--speed", demoSpeed, "doppler: the source's speed, m/s (default 30)");
  auto* demoFrequencyOption =
      demo->add_option("--frequency", demoFrequency, "doppler: the source's frequency, Hz (default 440)");

  auto* run = app.add_subcommand(
      "run", "simulate a scene file (particles or rigid2d): impetus run SCENE.json --steps N [--dt H] [--out FILE] "
             "[--every K] [--events FILE.csv] [--threads T] [--hash]");
  impetus::cli::RunOptions runOptions;
  run->add_option("scene", runOptions.scene, "scene file (JSON, docs/scene-format.md, docs/scene-format-2d.md)")
      ->required();
  run->add_option("--steps", runOptions.steps, "number of steps to take")->required();
  run->add_option("--dt", runOptions.dt, "time step, s (default 1/60)");
  run->add_option("--out", runOptions.out, "trajectory file: .csv or .json");
  run->add_option("--every", runOptions.every, "record every K-th step (default 1)");
  run->add_option("--events", runOptions.events, "rigid2d scenes: contact and joint events, .csv");
  run->add_option("--threads", runOptions.threads,
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
    return impetus::cli::runCalc(list, json, model, calc->remaining());
  }
  if (demo->parsed()) {
    impetus::cli::DemoOptions options;
    if (!demoOut.empty()) {
      options.outDir = demoOut;
    }
    if (demoSpeedOption->count() > 0) {
      options.speed = demoSpeed;
    }
    if (demoFrequencyOption->count() > 0) {
      options.frequency = demoFrequency;
    }
    return impetus::cli::runDemo(demoName, demoList, options);
  }
  if (run->parsed()) {
    return impetus::cli::runScene(runOptions);
  }
  return 2;
}
