// SPDX-License-Identifier: MIT
// The `tilesweep` command. Each line goes parse -> validate -> resolve -> print; nothing else
// happens here. A subcommand is a pair of functions, add<Name>Command (its options) and
// run<Name>Command (its work), and main only dispatches, so adding `check`, `render` or
// `audit` touches neither `resolve` nor main's structure.
#include "tilesweep/scene/file_write.h"
#include "tilesweep/scene/render.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#if TILESWEEP_HAVE_CHECK
#include "check_command.h"
#include "replay_command.h"

#include "tilesweep/oracle/exact/gmp_allocation.h"
#endif
#if TILESWEEP_HAVE_AUDIT
#include "audit_command.h"
#endif
#if TILESWEEP_HAVE_AUDIT && TILESWEEP_HAVE_CHECK
#include "merge_command.h"
#endif
#include "tilesweep/resolvers/library_resolver.h"
#include "tilesweep/resolvers/resolver_registry.h"
#include "tilesweep/scene/scene.h"

#ifndef TILESWEEP_CLI_VERSION
#error "TILESWEEP_CLI_VERSION must be defined by the build (cli/CMakeLists.txt does)"
#endif

namespace {

constexpr int kExitOk = 0;
constexpr int kExitSceneError = 1;  // at least one line was answered with {"error": ...}
constexpr int kExitUsage = 2;       // bad arguments, or FILE could not be read, or stdout failed

using tilesweep::resolvers::SceneResolver;

bool isBlank(std::string_view line) {
    return line.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos;
}

// ---- tilesweep resolve ------------------------------------------------------------------

struct ResolveOptions {
    std::string scalar = "float";
    std::string resolver = "core";
    std::string file = "-";
    std::string resolverCmd;      // an outside resolver to pass every scene through
    double resolverTimeout = 10;  // seconds per scene before it counts as hung
};

/// One output line for one scene line: the frames, or an error naming the field at fault.
template <class T>
std::string resolveLine(const std::string& line, SceneResolver& resolver, bool& failed) {
    // parse and validate
    tilesweep::SceneParse<T> parsed = tilesweep::parseScene<T>(line);
    if (!parsed.scene) {
        failed = true;
        return tilesweep::formatError(parsed.error);
    }
    // resolve and print
    const tilesweep::resolvers::Answer<T> answer = tilesweep::resolvers::resolveOne(resolver, *parsed.scene);
    if (answer.answered()) return tilesweep::formatFrames(answer.frames);
    failed = true;
    return tilesweep::formatError("resolve: " + answer.failure);
}

/// Answers every non-blank line of `in`, in order; returns the exit status.
template <class T>
int resolveLines(std::istream& in, std::ostream& out, SceneResolver& resolver) {
    bool failed = false;
    std::string line;
    while (std::getline(in, line)) {
        if (isBlank(line)) continue;
        // Flushed per line, so a harness can feed scenes through a pipe one at a time.
        out << resolveLine<T>(line, resolver, failed) << '\n' << std::flush;
    }
    return failed ? kExitSceneError : kExitOk;
}

CLI::App* addResolveCommand(CLI::App& app, ResolveOptions& options) {
    CLI::App* command = app.add_subcommand(
        "resolve", "Resolve scene lines (JSON Lines): one result line per scene, in order");
    command->add_option("--scalar", options.scalar, "The scalar type every number is rounded to")
        ->check(CLI::IsMember(std::vector<std::string>{"float", "double"}))
        ->capture_default_str();
    command
        ->add_option(
            "--resolver", options.resolver,
            "The implementation: core (production, in --scalar), float, double (production in that\n"
            "type), exact (rational reference), substep:N, substep-float:N, seed (the article's),\n"
            "twin, grid (game-style baselines), lib:PATH (a user's library), cmd:COMMAND (a process)")
        ->check(CLI::Validator(tilesweep::resolvers::checkResolverName, "NAME", "resolver"))
        ->capture_default_str();
    command
        ->add_option("--resolver-cmd", options.resolverCmd,
                     "Pass every scene through an outside resolver (a shell command speaking this\n"
                     "protocol) and print its answers, checked and re-printed in this format\n"
                     "(the same as --resolver cmd:CMD)")
        ->type_name("CMD");
    command->add_option("--resolver-timeout", options.resolverTimeout, "Seconds per scene for --resolver-cmd")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command->add_option("FILE", options.file, "The scene file; '-' or none reads standard input")
        ->type_name("PATH")
        ->capture_default_str();
    command->footer(
        "A scene line:\n"
        "  {\"name\": \"landing\", \"map\": {\"origin\": [0, 0], \"tile\": [16, 16],\n"
        "   \"rows\": [\"....\", \"####\"]}, \"box\": [4, 0, 8, 8], \"move\": [3, 20]}\n"
        "rows[0] is the top row, '#' solid, '-' one-way (blocks only a box landing on its top),\n"
        "'.' empty; y grows downward. \"box\" is [x, y, w, h];\n"
        "\"move\": [dx, dy] is one frame, \"moves\": [[dx, dy], ...] several, each starting where\n"
        "the last ended. A number is a JSON number or a hexfloat string (\"0x1.8p+3\"), rounded\n"
        "once to the scalar type. Unknown fields are ignored; blank lines are skipped.\n"
        "\n"
        "An output line, numbers in the shortest form that reads back to the same bits:\n"
        "  {\"frames\": [{\"pos\": [x, y], \"contacts\": [{\"tile\": [i, j], \"normal\": [nx, ny],\n"
        "   \"t\": t}], \"started_overlapping\": [[i, j]]}]}\n"
        "or, for a line that cannot be read, {\"error\": \"<field>: <problem>\"}.\n"
        "\n"
        "Exit status: 0 every line resolved; 1 some line was an error line (the others are still\n"
        "resolved); 2 bad arguments or FILE unreadable.");
    return command;
}

int runResolveCommand(const ResolveOptions& options) {
    // Open the input before anything is written, so an unreadable FILE writes no output.
    std::ifstream file;
    if (options.file != "-") {
        file.open(options.file);
        // A directory opens but cannot be read; peek() makes the first read fail here instead.
        if (file.is_open()) file.peek();
        if (!file.is_open() || file.bad()) {
            std::cerr << "tilesweep resolve: cannot read '" << options.file << "': " << std::strerror(errno)
                      << '\n';
            return kExitUsage;
        }
    }
    std::istream& in = options.file == "-" ? std::cin : file;

    // --resolver float / double name the production resolver in that scalar, whatever --scalar says.
    const std::string forced = tilesweep::resolvers::scalarForcedBy(options.resolver);
    const std::string scalar = forced.empty() ? options.scalar : forced;
    // --resolver-cmd: the outside process answers; its lines are read back exactly and printed
    // again, so a malformed answer becomes an error line naming what is wrong.
    const std::string name = options.resolverCmd.empty()
                                 ? options.resolver
                                 : std::string(tilesweep::resolvers::kCommandPrefix) + options.resolverCmd;
    if (name.rfind(tilesweep::resolvers::kLibraryPrefix, 0) == 0) {
        // A library may export one scalar's function only: the one asked for must be there.
        const std::string path = name.substr(std::string(tilesweep::resolvers::kLibraryPrefix).size());
        const std::string error = scalar == "double"
                                      ? tilesweep::resolvers::loadLibraryResolver<double>(path).error
                                      : tilesweep::resolvers::loadLibraryResolver<float>(path).error;
        if (!error.empty()) {
            std::cerr << "tilesweep resolve: --resolver " << options.resolver << ": " << error << '\n';
            return kExitUsage;
        }
    }
    std::string error;
    const std::unique_ptr<SceneResolver> resolver =
        tilesweep::resolvers::makeResolver(name, error, {options.resolverTimeout});
    if (!resolver) {
        std::cerr << "tilesweep resolve: --resolver " << name << ": " << error << '\n';
        return kExitUsage;
    }
    const int status = scalar == "double" ? resolveLines<double>(in, std::cout, *resolver)
                                          : resolveLines<float>(in, std::cout, *resolver);
    if (in.bad()) {
        std::cerr << "tilesweep resolve: error while reading '" << options.file << "'\n";
        return kExitUsage;
    }
    if (!std::cout) {
        std::cerr << "tilesweep resolve: error while writing the output\n";
        return kExitUsage;
    }
    return status;
}

// ---- tilesweep render -------------------------------------------------------------------

constexpr int kExitRenderError = 1;  // the file or the scene could not be read, or OUT not written

struct RenderOptions {
    std::string scalar = "float";
    int index = 0;
    std::string file;
    std::string output;
};

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options) {
    CLI::App* command =
        app.add_subcommand("render", "Draw one scene and its resolved frames as an SVG picture");
    command->add_option("--scalar", options.scalar, "The scalar type every number is rounded to")
        ->check(CLI::IsMember(std::vector<std::string>{"float", "double"}))
        ->capture_default_str();
    command->add_option("--index", options.index, "Which scene of the file, counting non-blank lines from 0")
        ->check(CLI::Range(0, std::numeric_limits<int>::max()))
        ->capture_default_str();
    command->add_option("SCENE_FILE", options.file, "The scene file (JSON Lines)")
        ->type_name("PATH")
        ->required();
    command->add_option("-o,--output", options.output, "The SVG file to write")
        ->type_name("OUT.svg")
        ->required();
    command->footer(
        "The picture shows the tiles, the box at the start and at each frame end, the path of\n"
        "its centre, the tiles hit with their normals, and the cells it started overlapping.\n"
        "The frames come from the production resolver. OUT is replaced atomically (written to\n"
        "OUT.tmp, then renamed); on an error nothing is written.\n"
        "\n"
        "Exit status: 0 written; 1 the file or the scene could not be read, or OUT could not be\n"
        "written; 2 bad arguments.");
    return command;
}

/// The `index`-th non-blank line of `path`, or an error message in `error`.
std::string readSceneLine(const std::string& path, int index, std::string& error) {
    std::ifstream file(path);
    // A directory opens but cannot be read; peek() makes the first read fail here instead.
    if (file.is_open()) file.peek();
    if (!file.is_open() || file.bad()) {
        error = "cannot read '" + path + "': " + std::strerror(errno);
        return {};
    }
    int seen = 0;
    std::string line;
    while (std::getline(file, line)) {
        if (isBlank(line)) continue;
        if (seen == index) return line;
        ++seen;
    }
    if (file.bad())
        error = "error while reading '" + path + "'";
    else
        error = "'" + path + "' has " + std::to_string(seen) + " scene" + (seen == 1 ? "" : "s") +
                ", no scene at index " + std::to_string(index);
    return {};
}

/// The picture of one scene line, or an error message in `error`.
template <class T>
std::string renderLine(const std::string& line, std::string& error) {
    tilesweep::SceneParse<T> parsed = tilesweep::parseScene<T>(line);
    if (!parsed.scene) {
        error = parsed.error;
        return {};
    }
    try {
        return tilesweep::renderSceneSvg(*parsed.scene, tilesweep::runScene(*parsed.scene));
    } catch (const std::exception& exception) {
        error = std::string("render: ") + exception.what();
        return {};
    }
}

int runRenderCommand(const RenderOptions& options) {
    std::string error;
    const std::string line = readSceneLine(options.file, options.index, error);
    std::string svg;
    if (error.empty())
        svg = options.scalar == "double" ? renderLine<double>(line, error) : renderLine<float>(line, error);
    if (error.empty()) (void)tilesweep::writeFileWhole(options.output, svg, error);
    if (!error.empty()) {
        std::cerr << "tilesweep render: " << error << '\n';
        return kExitRenderError;
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
#if TILESWEEP_HAVE_CHECK
    // Before any exact number exists: the judge's rationals then reuse freed blocks.
    tilesweep::oracle::useCachedGmpAllocation();
#endif
    std::ios::sync_with_stdio(false);
    CLI::App app{
        "tilesweep: exact swept-AABB collision of a box moving through a 2D tile map.\n"
        "Every decision (which tiles are hit, when, on which face) is exact; final positions are\n"
        "the exact ones rounded toward the start, so a box never ends inside a tile.",
        "tilesweep"};
    app.set_version_flag("--version", std::string("tilesweep ") + TILESWEEP_CLI_VERSION);
    app.require_subcommand(1);
    app.footer("Run 'tilesweep <command> --help' for a command's input and output formats.");

    ResolveOptions resolveOptions;
    CLI::App* resolveCommand = addResolveCommand(app, resolveOptions);
    RenderOptions renderOptions;
    CLI::App* renderCommand = addRenderCommand(app, renderOptions);
#if TILESWEEP_HAVE_CHECK
    tilesweep::cli::CheckOptions checkOptions;
    CLI::App* checkCommand = tilesweep::cli::addCheckCommand(app, checkOptions);
    tilesweep::cli::ReplayOptions replayOptions;
    CLI::App* replayCommand = tilesweep::cli::addReplayCommand(app, replayOptions);
#endif
#if TILESWEEP_HAVE_AUDIT
    tilesweep::cli::AuditOptions auditOptions;
    CLI::App* auditCommand = tilesweep::cli::addAuditCommand(app, auditOptions);
    for (int k = 0; k < argc; ++k) {  // as typed, an argument that is empty or has a space quoted
        const std::string arg = argv[k];
        auditOptions.commandLine += k == 0 ? std::string("tilesweep")
                                    : arg.empty() || arg.find(' ') != std::string::npos ? " \"" + arg + "\""
                                                                                        : " " + arg;
    }
#endif
#if TILESWEEP_HAVE_AUDIT && TILESWEEP_HAVE_CHECK
    tilesweep::cli::MergeOptions mergeOptions;
    CLI::App* mergeCommand = tilesweep::cli::addMergeCommand(app, mergeOptions);
#endif

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help and --version end here with status 0; a usage error gets the usage status.
        return app.exit(error) == 0 ? kExitOk : kExitUsage;
    }

    try {
        if (resolveCommand->parsed()) return runResolveCommand(resolveOptions);
        if (renderCommand->parsed()) return runRenderCommand(renderOptions);
#if TILESWEEP_HAVE_CHECK
        if (checkCommand->parsed()) return tilesweep::cli::runCheckCommand(checkOptions);
        if (replayCommand->parsed()) return tilesweep::cli::runReplayCommand(replayOptions);
#endif
#if TILESWEEP_HAVE_AUDIT
        if (auditCommand->parsed()) return tilesweep::cli::runAuditCommand(auditOptions);
#endif
#if TILESWEEP_HAVE_AUDIT && TILESWEEP_HAVE_CHECK
        if (mergeCommand->parsed()) return tilesweep::cli::runMergeCommand(mergeOptions);
#endif
    } catch (const std::exception& error) {
        std::cerr << "tilesweep: " << error.what() << '\n';
        return kExitUsage;
    }
    return kExitUsage;  // require_subcommand(1) makes this unreachable
}
