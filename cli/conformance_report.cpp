// SPDX-License-Identifier: MIT
#include "conformance_report.h"

#include "tilesweep/scene/file_write.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tilesweep::cli {
namespace {

std::string slug(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0;
        if (keep)
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!out.empty() && out.back() != '-')
            out += '-';
    }
    while (!out.empty() && out.back() == '-') out.pop_back();
    return out.substr(0, 40);
}

std::string fixed(double v, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

/// The per-case failure rate estimated from a run that stops at each failure: failures over
/// cases run (every failing run ran one failing case after its passing ones).
std::string failureRate(const CheckRow& r) {
    const int run = r.cases + r.failures;
    if (r.failures == 0) return "0";
    const double rate = static_cast<double>(r.failures) / run;
    return fixed(100.0 * rate, rate < 0.001 ? 3 : 1) + "% (1 in " + fixed(1.0 / rate, 0) + ")";
}

/// A property's verdict: it failed, it never ran (the budget ended before its first run, so it
/// says nothing of the resolver), or it held over every case it ran.
const char* verdictOf(const CheckRow& r) {
    if (r.failures > 0) return "**fails**";
    if (r.runs == 0) return "not run (the budget ended first)";
    return r.coverageShortfalls > 0 ? "holds (insufficient coverage)" : "holds";
}

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

/// Markdown table cells must not hold a '|' or a newline.
std::string cell(std::string text) {
    for (char& c : text)
        if (c == '|' || c == '\n') c = ' ';
    return text;
}

}  // namespace

void writeConformanceReport(const std::vector<ConformanceEntry>& entries, const std::string& file,
                            const std::string& pictureDir, const std::string& rates) {
    const std::filesystem::path reportPath(file);
    const std::filesystem::path reportDir = reportPath.parent_path().empty() ? "." : reportPath.parent_path();
    std::filesystem::create_directories(reportDir);
    std::filesystem::create_directories(pictureDir);
    std::ostringstream md;
    md << "# Conformance: resolvers held to the contract\n\n"
          "Written by `tilesweep audit --resolver-cmd` (see docs/verifier.md, \"Holding any resolver to the "
          "contract\"). Each resolver is an outside process speaking `tilesweep resolve`'s JSON Lines "
          "protocol; every claim about results of the property suite runs against it, each failure is "
          "shrunk along RapidCheck's shrinks, and the smallest counterexample of each property is shown with "
          "its picture. "
          "A failure rate is failing cases over cases run (a run stops at its first failure; rounds go on "
          "with a new seed until the budget is spent). Time includes shrinking, which asks the resolver "
          "again at "
          "every step; the first counterexample's time is that of the first failing run, shrinking "
          "included. Each round's scenes go to the resolver in one batch; shrinking asks for each "
          "step's candidates in batches of 16.\n\n";
    md << "| resolver | properties held | properties failed | properties not run | cases run | cases/s "
          "|\n|---|---:|---:|---:|---:|---:|\n";
    for (const ConformanceEntry& e : entries) {
        int held = 0, failed = 0, notRun = 0, cases = 0;
        for (const CheckRow& r : e.run.rows) {
            (r.failures > 0 ? failed : (r.runs == 0 ? notRun : held)) += 1;
            cases += r.cases + r.failures;
        }
        md << "| " << e.label << " | " << held << " | " << failed << " | " << notRun << " | " << cases
           << " | " << fixed(e.run.wallSeconds > 0 ? cases / e.run.wallSeconds : 0.0, 0) << " |\n";
    }
    if (!rates.empty()) md << "\n## Rates and tolerances\n\n" << rates;
    for (const ConformanceEntry& e : entries) {
        const CheckOptions& o = e.options;
        md << "\n## " << e.label << "\n\n";
        md << "- command: `" << (o.resolverCmd.empty() ? std::string("(built-in resolver)") : o.resolverCmd)
           << "`\n";
        md << "- claims: " << o.claims << ", scalar: " << (o.scalar.empty() ? "float" : o.scalar) << ", "
           << o.cases << " cases per property per round, first seed " << o.seed << ", budget "
           << fixed(o.seconds, 0) << " s on " << e.run.jobs << " job" << (e.run.jobs == 1 ? "" : "s") << " ("
           << fixed(e.run.wallSeconds, 1) << " s wall)\n\n";
        md << "| property | claim | verdict | cases run | failures | failure rate | cases/s | time s | first "
              "counterexample after |\n"
              "|---|---|---|---:|---:|---|---:|---:|---:|\n";
        for (const CheckRow& r : e.run.rows)
            md << "| " << r.property << " | " << r.claim << " | " << verdictOf(r) << " | "
               << r.cases + r.failures << " | " << r.failures << " | " << failureRate(r) << " | "
               << fixed(r.seconds > 0 ? r.cases / r.seconds : 0.0, 0) << " | " << fixed(r.seconds, 1) << " | "
               << (r.failures == 0 ? std::string("") : fixed(r.secondsToFirstFailure, 1) + " s") << " |\n";
        bool anyFailure = false;
        for (const CheckRow& r : e.run.rows) anyFailure = anyFailure || r.failures > 0;
        if (!anyFailure) continue;
        md << "\n### Smallest counterexamples: " << e.label << "\n";
        // One counterexample per claim: the shortest scene among the properties that state it (the
        // same claim over other families fails for the same reason), the others named beside it.
        std::map<std::string, const CheckRow*> smallest;
        std::map<std::string, std::vector<std::string>> alsoFailing;
        for (const CheckRow& r : e.run.rows) {
            if (r.failures == 0) continue;
            const CheckRow*& kept = smallest[r.claim];
            const bool better =
                kept == nullptr ||
                (!r.smallestScene.empty() &&
                 (kept->smallestScene.empty() || r.smallestScene.size() < kept->smallestScene.size()));
            if (kept != nullptr) alsoFailing[r.claim].push_back(better ? kept->property : r.property);
            if (better) kept = &r;
        }
        for (const CheckRow& r : e.run.rows) {
            if (r.failures == 0 || smallest[r.claim] != &r) continue;
            md << "\n**" << r.property << "**: " << cell(firstLine(r.smallestFailure)) << "\n";
            if (!alsoFailing[r.claim].empty()) {
                md << "\nThe same claim (" << r.claim << ") also fails in:";
                for (const std::string& other : alsoFailing[r.claim]) md << " " << other;
                md << ".\n";
            }
            md << "\n";
            if (r.smallestScene.empty()) continue;
            md << "```json\n" << r.smallestScene << "\n```\n";
            if (!r.smallestPicture.empty() && std::filesystem::exists(r.smallestPicture)) {
                const std::filesystem::path picture =
                    std::filesystem::path(pictureDir) / (slug(e.label) + "-" + r.property + ".svg");
                std::filesystem::copy_file(r.smallestPicture, picture,
                                           std::filesystem::copy_options::overwrite_existing);
                const std::filesystem::path corpus = std::filesystem::path(r.smallestCorpus);
                const std::filesystem::path corpusCopy =
                    picture.parent_path() / (picture.stem().string() + ".jsonl");
                if (!r.smallestCorpus.empty() && std::filesystem::exists(corpus))
                    std::filesystem::copy_file(corpus, corpusCopy,
                                               std::filesystem::copy_options::overwrite_existing);
                const std::string relative = std::filesystem::relative(picture, reportDir).generic_string();
                const std::string relativeCorpus =
                    std::filesystem::relative(corpusCopy, reportDir).generic_string();
                md << "\n![" << r.property << "](" << relative
                   << ")\n\nRegression file (with the resolver's answer "
                   << "beside the exact one): [" << relativeCorpus << "](" << relativeCorpus << ")\n";
            }
        }
    }
    if (std::string error; !writeFileWhole(file, md.str(), error)) throw std::runtime_error(error);
}

}  // namespace tilesweep::cli
