// SPDX-License-Identifier: MIT
#include "merge_command.h"

#include "check_command.h"
#include "conformance_report.h"
#include "shard.h"

#include "tilesweep/audit/engine_rates.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace tilesweep::cli {
namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Copies every regression file and picture of `from` into `to`; returns how many.
int copyCorpus(const std::filesystem::path& from, const std::filesystem::path& to) {
    int copied = 0;
    std::error_code error;
    if (!std::filesystem::is_directory(from, error)) return 0;
    std::filesystem::create_directories(to);
    for (const auto& entry : std::filesystem::directory_iterator(from)) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".jsonl" && extension != ".svg") continue;
        std::filesystem::copy_file(entry.path(), to / entry.path().filename(),
                                   std::filesystem::copy_options::overwrite_existing);
        ++copied;
    }
    return copied;
}

/// A check file's shard of a run: the file, its options as read back, and its K/N.
struct CheckShard {
    std::string file;
    CheckOptions options;
    Shard shard;
};

/// Refuses check shards of one resolver that are not distinct slices of one run: the same
/// seed, claims, scalar type, cases a round and shard count, each K given once. Adding up
/// anything else would count cases twice, or add cases of different runs.
void requireOneRun(const std::vector<CheckShard>& shards) {
    const CheckShard& first = shards.front();
    for (std::size_t k = 1; k < shards.size(); ++k) {
        const CheckShard& s = shards[k];
        auto differs = [&](const std::string& field, const std::string& got, const std::string& want) {
            return std::invalid_argument(s.file + ": " + field + " " + got + " differs from " + first.file +
                                         "'s " + want + " (a shard of another run)");
        };
        if (s.options.seed != first.options.seed)
            throw differs("seed", std::to_string(s.options.seed), std::to_string(first.options.seed));
        if (s.options.claims != first.options.claims)
            throw differs("claims", "'" + s.options.claims + "'", "'" + first.options.claims + "'");
        if (s.options.scalar != first.options.scalar)
            throw differs("scalar", s.options.scalar, first.options.scalar);
        if (s.options.cases != first.options.cases)
            throw differs("cases", std::to_string(s.options.cases), std::to_string(first.options.cases));
        if (s.shard.count != first.shard.count)
            throw differs("shard count", std::to_string(s.shard.count), std::to_string(first.shard.count));
        for (std::size_t e = 0; e < k; ++e)
            if (shards[e].shard.index == s.shard.index)
                throw std::invalid_argument(s.file + ": shard " + s.options.shard +
                                            " is given twice (also in " + shards[e].file + ")");
    }
}

}  // namespace

CLI::App* addMergeCommand(CLI::App& app, MergeOptions& options) {
    CLI::App* command =
        app.add_subcommand("merge", "Add up the reports of shards (check --json files and rates.json files)");
    command->add_option("files", options.files, "check --json files and rates.json files of the shards")
        ->required()
        ->check(CLI::ExistingFile);
    command
        ->add_option("--out", options.outDir, "Where conformance.md, rates.json, check-*.json and corpus/ go")
        ->capture_default_str();
    command->footer(
        "Check files are grouped by resolver command and added up property by property (cases,\n"
        "failures, coverage; the smallest counterexample of all shards is kept), and their corpora\n"
        "copied into OUT/corpus/. The check files of one resolver must be distinct shards of one run\n"
        "(same seed, claims, scalar, cases and shard count). Rates files must come from one run (same\n"
        "seed, cases, shard count, engines and families) and distinct shards; their counts add up and\n"
        "their tolerances take the largest. Anything else is refused before a file is written.\n"
        "\n"
        "Exit status: 0 every claim held; 1 some resolver broke a claim; 2 bad input.");
    return command;
}

int runMergeCommand(const MergeOptions& options) {
    std::map<std::string, std::vector<CheckRun>> checks;  // by resolver command, in file order
    std::map<std::string, std::vector<CheckShard>> checkShards;
    std::map<std::string, CheckOptions> checkOptions;
    std::vector<std::string> order;
    std::vector<audit::RatesResult> rates;
    std::vector<std::string> ratesFiles;
    int corpusFiles = 0;
    try {
        for (const std::string& file : options.files) {
            const std::string text = readFile(file);
            if (text.find("\"tilesweep-rates\"") != std::string::npos) {
                rates.push_back(audit::readRatesJson(text));
                ratesFiles.push_back(file);
                continue;
            }
            CheckOptions o;
            CheckRun run = readCheckJson(text, o);
            Shard shard;
            std::string shardError;
            if (!parseShard(o.shard, shard, shardError)) throw std::runtime_error(file + ": " + shardError);
            checkShards[o.resolverCmd].push_back({file, o, shard});
            if (checks.find(o.resolverCmd) == checks.end()) order.push_back(o.resolverCmd);
            checks[o.resolverCmd].push_back(std::move(run));
            checkOptions[o.resolverCmd] = o;
        }
        for (const auto& [command, shards] : checkShards) requireOneRun(shards);
        if (!rates.empty()) (void)audit::mergeRates(rates, ratesFiles);  // refused before anything is written
    } catch (const std::exception& error) {
        std::cerr << "tilesweep merge: " << error.what() << '\n';
        return 2;
    }

    bool allHeld = true;
    std::vector<ConformanceEntry> entries;
    std::string ratesSection;
    try {
        std::filesystem::create_directories(options.outDir);
        for (const std::string& command : order)
            for (const CheckShard& s : checkShards[command])
                corpusFiles +=
                    copyCorpus(s.options.corpusDir, std::filesystem::path(options.outDir) / "corpus");
        for (std::size_t k = 0; k < order.size(); ++k) {
            ConformanceEntry entry;
            entry.label = order[k].empty() ? "tilesweep (built-in)" : order[k];
            entry.options = checkOptions[order[k]];
            entry.options.corpusDir = (std::filesystem::path(options.outDir) / "corpus").string();
            entry.run = mergeCheckRuns(checks[order[k]]);
            for (const CheckRow& r : entry.run.rows) allHeld = allHeld && r.failures == 0;
            const std::string json =
                (std::filesystem::path(options.outDir) / ("check-" + std::to_string(k + 1) + ".json"))
                    .string();
            std::ofstream(json) << checkJson(entry.options, entry.run);
            std::printf("%-40s %zu shards, %zu properties -> %s\n", entry.label.c_str(),
                        checks[order[k]].size(), entry.run.rows.size(), json.c_str());
            entries.push_back(std::move(entry));
        }
        if (!rates.empty()) {
            const audit::RatesResult merged = audit::mergeRates(rates, ratesFiles);
            const std::string json = (std::filesystem::path(options.outDir) / "rates.json").string();
            std::ofstream(json) << audit::ratesJson(merged);
            ratesSection = audit::ratesMarkdown(merged);
            std::printf("rates: %zu shards of %d -> %s\n", merged.shards.size(), merged.config.shardCount,
                        json.c_str());
            if (static_cast<int>(merged.shards.size()) < merged.config.shardCount)
                std::printf("note: %d of %d shards merged; the rates cover only their cases\n",
                            static_cast<int>(merged.shards.size()), merged.config.shardCount);
        }
        const std::string report = (std::filesystem::path(options.outDir) / "conformance.md").string();
        writeConformanceReport(entries, report, (std::filesystem::path(options.outDir) / "pictures").string(),
                               ratesSection);
        std::printf("corpus: %d files -> %s/corpus\nreport: %s\n", corpusFiles, options.outDir.c_str(),
                    report.c_str());
    } catch (const std::exception& error) {
        std::cerr << "tilesweep merge: " << error.what() << '\n';
        return 2;
    }
    return allHeld ? 0 : 1;
}

}  // namespace tilesweep::cli
