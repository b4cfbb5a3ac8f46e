// SPDX-License-Identifier: MIT
#include "property_suite.h"

#include "all_claims.h"
#include "answer_cache.h"
#include "coverage_judgement.h"
#include "generators.h"

#include "tilesweep/oracle/exact/exact_resolve.h"
#include "tilesweep/resolvers/resolver_registry.h"
#include "tilesweep/scene/file_write.h"
#include "tilesweep/scene/render.h"
#include "tilesweep/scene/scalar_text.h"

#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>

namespace tilesweep::properties {
namespace {

std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return h;
}

/// Writes `text` to `path` whole or not at all (writeFileWhole), its directory made first.
void writeAtomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::string error;
    if (!writeFileWhole(path.string(), text, error)) throw std::runtime_error(error);
}

/// The seed of a run's coverage round `round` (> 0): far from the seeds `tilesweep check` gives
/// its own later rounds (seed + 1, seed + 2, ...).
std::uint64_t coverageRoundSeed(std::uint64_t seed, int round) {
    std::uint64_t h = seed ^ (0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(round));
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

/// Judges every floor on the cases seen so far; fills the outcome's coverage fields when
/// `final`. Returns whether some floor is still undecided.
bool judgeFloors(const std::vector<CoverageFloor>& floors, PropertyOutcome& outcome, bool final) {
    bool undecided = false;
    for (const CoverageFloor& floor : floors) {
        const auto found = outcome.tagCounts.find(floor.tag);
        const long long hits = found == outcome.tagCounts.end() ? 0 : found->second;
        const FloorVerdict verdict = judgeFloor(hits, outcome.cases, floor.fraction);
        undecided = undecided || verdict == FloorVerdict::Undecided;
        if (!final || verdict == FloorVerdict::Met) continue;
        const ShareInterval share = wilsonInterval(hits, outcome.cases);
        const double seen = outcome.cases > 0 ? double(hits) / outcome.cases : 0.0;
        std::string& text =
            verdict == FloorVerdict::Short ? outcome.coverageShortfall : outcome.coverageUndecided;
        text += (text.empty() ? "" : "; ") + std::string("'") + floor.tag + "' in " +
                detail::percentText(seen) + " of " + std::to_string(outcome.cases) + " cases (between " +
                detail::percentText(share.low) + " and " + detail::percentText(share.high) +
                " at error rate 1e-9), " +
                (verdict == FloorVerdict::Short ? "below" : "not settled against") + " the floor of " +
                detail::percentText(floor.fraction);
    }
    return undecided;
}

/// RapidCheck's size for case `i` of `cases`: every size from 0 to kMaxSize, evenly spread, the
/// largest reached.
int sizeFor(int i, int cases) {
    constexpr int kMaxSize = 100;
    if (cases <= 1) return kMaxSize;
    return static_cast<int>(static_cast<long long>(i) * kMaxSize / (cases - 1));
}

/// The coverage tags of one case, as the floors count them: its family, the classes of its
/// scene, and the rounding rule's exception per family.
template <class T>
std::vector<std::string> caseTags(const GeneratedScene<T>& g) {
    std::vector<std::string> tags{std::string("family:") + familyName(g.family)};
    for (std::string& tag : classifyScene(g.scene)) {
        if (tag == "rounded-down") tags.push_back(std::string("rounded-down@") + familyName(g.family));
        tags.push_back(std::move(tag));
    }
    return tags;
}

/// One drawn case: its value, and what it shrinks to.
template <class T>
struct DrawnCase {
    rc::Shrinkable<GeneratedScene<T>> shrinkable;
    GeneratedScene<T> value;
};

/// Every scene the claim asks for on `cases`, to the cache in one batch, when the resolver is in
/// another process (an in-process resolver gains nothing from a batch).
template <class T>
void askInOneBatch(const Claim<T>& claim, const std::vector<const GeneratedScene<T>*>& cases,
                   AnswerCache& cache) {
    if (!cache.outside()) return;
    std::vector<Scene<T>> asked;
    for (const GeneratedScene<T>* g : cases)
        for (Scene<T>& s : scenesAskedBy(claim, g->scene)) asked.push_back(std::move(s));
    cache.fill(asked);
}

/// Shrinks a failing case, greedily as RapidCheck does: the first shrink that still fails takes
/// its place, until none does or the budget is spent. Each step's candidates are asked for in
/// batches. Returns whether the budget stopped it.
template <class T>
bool shrinkCase(const Claim<T>& claim, DrawnCase<T>& failing, std::string& message, AnswerCache& cache,
                double budgetSeconds) {
    constexpr std::size_t kCandidatesPerBatch = 16;
    const auto started = std::chrono::steady_clock::now();
    const auto spent = [&] {
        return budgetSeconds > 0 &&
               std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
                   budgetSeconds;
    };
    for (bool progressed = true; progressed;) {
        progressed = false;
        rc::Seq<rc::Shrinkable<GeneratedScene<T>>> shrinks = failing.shrinkable.shrinks();
        for (bool more = true; more && !progressed;) {
            if (spent()) return true;
            std::vector<DrawnCase<T>> candidates;
            while (candidates.size() < kCandidatesPerBatch) {
                rc::Maybe<rc::Shrinkable<GeneratedScene<T>>> next = shrinks.next();
                if (!next) {
                    more = false;
                    break;
                }
                try {
                    GeneratedScene<T> value = next->value();
                    candidates.push_back({std::move(*next), std::move(value)});
                } catch (const rc::GenerationFailure&) {
                }
            }
            std::vector<const GeneratedScene<T>*> values;
            for (const DrawnCase<T>& c : candidates) values.push_back(&c.value);
            cache.clear();
            askInOneBatch(claim, values, cache);
            for (DrawnCase<T>& c : candidates) {
                std::string why = checkClaim(claim, c.value.scene, cache);
                if (why.empty()) continue;
                failing = std::move(c);
                message = std::move(why);
                progressed = true;
                break;
            }
        }
    }
    return false;
}

/// One round of a claim: `cases` cases drawn from `seed`, their scenes asked for in one batch,
/// then each judged. With `options.shrink` the round stops at its first failure and shrinks it;
/// without, every case is judged and the failures counted, the first one kept unshrunk.
template <class T>
PropertyOutcome runClaimOnce(const std::string& propertyName, const Claim<T>& claim, Family family,
                             const RunOptions& options, AnswerCache& cache) {
    PropertyOutcome outcome;
    const rc::Gen<GeneratedScene<T>> gen = genScene<T>(family);
    rc::Random random(options.seed);
    std::vector<DrawnCase<T>> drawn;
    drawn.reserve(static_cast<std::size_t>(std::max(options.cases, 0)));
    for (int i = 0, discarded = 0;
         static_cast<int>(drawn.size()) < options.cases && discarded <= 10 * options.cases; ++i) {
        rc::Shrinkable<GeneratedScene<T>> shrinkable = gen(random.split(), sizeFor(i, options.cases));
        try {
            GeneratedScene<T> value = shrinkable.value();
            drawn.push_back({std::move(shrinkable), std::move(value)});
        } catch (const rc::GenerationFailure&) {
            ++discarded;
        }
    }
    std::vector<const GeneratedScene<T>*> values;
    for (const DrawnCase<T>& c : drawn) values.push_back(&c.value);
    cache.clear();
    askInOneBatch(claim, values, cache);

    std::optional<std::size_t> firstFailure;
    std::string message;
    int counted = 0;
    for (std::size_t k = 0; k < drawn.size(); ++k) {
        for (const std::string& tag : caseTags(drawn[k].value)) ++outcome.tagCounts[tag];
        std::string why = checkClaim(claim, drawn[k].value.scene, cache);
        if (why.empty()) {
            ++outcome.cases;
            continue;
        }
        if (!firstFailure) {
            firstFailure = k;
            message = why;
            if (options.onFirstFailure) options.onFirstFailure(why, formatScene(drawn[k].value.scene));
        }
        ++counted;
        if (options.shrink) break;
    }
    outcome.passed = counted == 0;
    if (outcome.passed) return outcome;

    DrawnCase<T> failing = drawn[*firstFailure];
    outcome.failedCases = counted;
    if (!options.shrink) {
        outcome.sceneLine = formatScene(failing.value.scene);
        outcome.failure = message;
        outcome.message = message + "\n(" + std::to_string(counted) + " of " + std::to_string(drawn.size()) +
                          " cases failed; the first, not shrunk) " + familyName(failing.value.family) +
                          " scene: " + outcome.sceneLine;
        return outcome;
    }
    if (shrinkCase(claim, failing, message, cache, options.shrinkSeconds))
        message += " (shrinking stopped after the --shrink-seconds budget)";
    const GeneratedScene<T>& smallest = failing.value;
    outcome.sceneLine = formatScene(smallest.scene);
    outcome.failure = message;
    outcome.message = message + "\n" + familyName(smallest.family) + " scene: " + outcome.sceneLine;
    if (options.corpusDir.empty()) return outcome;

    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(outcome.sceneLine)));
    const std::filesystem::path file =
        std::filesystem::path(options.corpusDir) / (propertyName + "-" + std::string(hash, 8) + ".jsonl");
    // An outside resolver's failure carries its command and its answer beside the exact one; the
    // picture shows what it did, or the exact frames when it gave no answer.
    const resolvers::Answer<T> answer = resolvers::resolveOne<T>(cache, smallest.scene);
    std::string extra;
    std::vector<FrameResult<T>> pictured = answer.frames;
    if (cache.outside()) {
        nlohmann::ordered_json fields;
        fields["resolver_cmd"] = cache.name();
        const std::string text = !answer.text.empty() ? answer.text
                                 : answer.answered()  ? formatFrames(answer.frames)
                                                      : "(no answer: " + answer.failure + ")";
        const nlohmann::ordered_json parsedAnswer = nlohmann::ordered_json::parse(text, nullptr, false);
        fields["resolver_answer"] = parsedAnswer.is_discarded() ? nlohmann::ordered_json(text) : parsedAnswer;
        const std::vector<FrameResult<T>> exact = oracle::resolveSceneExactRounded(smallest.scene);
        fields["exact_answer"] = nlohmann::ordered_json::parse(formatFrames(exact));
        extra = fields.dump();
        if (!answer.answered()) pictured = exact;
    } else if (!answer.answered()) {
        pictured = runScene(smallest.scene);
    }
    writeAtomically(file, corpusLine(outcome.sceneLine, propertyName, options.seed, detail::scalarName<T>(),
                                     message, extra) +
                              "\n");
    outcome.corpusFile = file.string();
    std::filesystem::path picture = file;
    picture.replace_extension(".svg");
    writeAtomically(picture, renderSceneSvg(smallest.scene, pictured));
    outcome.pictureFile = picture.string();
    return outcome;
}

/// A claim's run: `options.cases` cases, then, while some coverage floor is undecided (neither
/// certainly met nor certainly short: coverage_judgement.h), rounds of as many cases again as
/// have run, from seeds of their own, up to the cap. Every case of every round checks the claim.
/// The tags come from the scene's exact resolution and tilesweep's own decision path
/// (classifyScene), never from an outside resolver's answers, so a shortfall is the generator's.
template <class T>
PropertyOutcome runClaim(const std::string& propertyName, const Claim<T>& claim, Family family,
                         const std::vector<CoverageFloor>& floors, const RunOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    std::string error;
    const std::unique_ptr<SceneResolver> core =
        options.resolver == nullptr ? resolvers::makeResolver("core", error) : nullptr;
    AnswerCache cache(options.resolver != nullptr ? *options.resolver : *core);
    const long long cap =
        options.maxCases > 0 ? options.maxCases : std::max(8LL * options.cases, kDefaultCoverageCases);
    PropertyOutcome outcome;
    RunOptions round = options;
    for (int r = 0;; ++r) {
        if (r > 0) {
            round.seed = coverageRoundSeed(options.seed, r);
            round.cases = static_cast<int>(std::min<long long>(outcome.cases, cap - outcome.cases));
        }
        PropertyOutcome part = runClaimOnce<T>(propertyName, claim, family, round, cache);
        const int casesBefore = outcome.cases;
        outcome.cases += part.cases;
        for (const auto& [tag, count] : part.tagCounts) outcome.tagCounts[tag] += count;
        if (!part.passed) {
            part.cases = outcome.cases;
            part.tagCounts = outcome.tagCounts;
            if (r > 0)
                part.message += "\n(in coverage round " + std::to_string(r) + ": seed " +
                                std::to_string(round.seed) + ", " + std::to_string(round.cases) +
                                " cases, after " + std::to_string(casesBefore) + " that passed)";
            outcome = part;
            break;
        }
        outcome.passed = true;
        const bool undecided = judgeFloors(floors, outcome, false);
        if (!undecided || outcome.cases >= cap || part.cases == 0) {
            judgeFloors(floors, outcome, true);
            break;
        }
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return outcome;
}

/// The property of `claim` over `property`'s family and floors, in T.
template <class T>
Property propertyOf(const Claim<T>& claim, const std::string& name, Family family,
                    std::vector<CoverageFloor> floors) {
    const std::string scalar = detail::scalarName<T>();
    const std::string fullName = name + "_" + scalar;
    const Claim<T>* held = &claim;
    std::vector<CoverageFloor> judged = floors;
    return {fullName,
            claim.name,
            claim.scope,
            scalar,
            std::move(floors),
            [fullName, held, family, judged](const RunOptions& o) {
                return runClaim<T>(fullName, *held, family, judged, o);
            }};
}

/// Every property of every claim, in T, in the order the claims are gathered (all_claims.cpp).
template <class T>
void addAll(std::vector<Property>& out) {
    for (const Claim<T>& claim : allClaims<T>())
        for (const PropertyOf& p : claim.properties)
            out.push_back(propertyOf(claim, p.name, p.family, p.floors));
}

}  // namespace

const std::vector<Property>& allProperties() {
    static const std::vector<Property> properties = [] {
        std::vector<Property> out;
        addAll<float>(out);
        addAll<double>(out);
        return out;
    }();
    return properties;
}

Property makeProperty(const std::string& name, const std::string& claimName, const std::string& scalar,
                      const std::string& family, std::vector<CoverageFloor> floors) {
    Family chosen = Family::Mixed;
    bool known = family == familyName(Family::Mixed);
    for (const Family f : allFamilies())
        if (family == familyName(f)) {
            chosen = f;
            known = true;
        }
    if (!known) throw std::invalid_argument("no family '" + family + "'");
    if (scalar != "float" && scalar != "double") throw std::invalid_argument("no scalar '" + scalar + "'");
    const bool isFloat = scalar == "float";
    if (isFloat ? findClaim<float>(claimName) == nullptr : findClaim<double>(claimName) == nullptr)
        throw std::invalid_argument("no claim '" + claimName + "'");
    Property made = isFloat ? propertyOf(*findClaim<float>(claimName), name, chosen, std::move(floors))
                            : propertyOf(*findClaim<double>(claimName), name, chosen, std::move(floors));
    made.name = name;
    return made;
}

RunOptions optionsFromEnvironment() {
    RunOptions options;
    if (const char* seed = std::getenv("TILESWEEP_PROPERTY_DEFAULT_SEED"))
        options.seed = std::strtoull(seed, nullptr, 10);
    if (const char* seed = std::getenv("TILESWEEP_PROPERTY_SEED"))
        options.seed = std::strtoull(seed, nullptr, 10);
    if (const char* cases = std::getenv("TILESWEEP_PROPERTY_CASES")) options.cases = std::atoi(cases);
    if (const char* dir = std::getenv("TILESWEEP_CORPUS_DIR")) options.corpusDir = dir;
    return options;
}

std::string corpusLine(const std::string& sceneLine, const std::string& property, std::uint64_t seed,
                       const std::string& scalar, const std::string& failure, const std::string& extra) {
    nlohmann::ordered_json line = nlohmann::ordered_json::parse(sceneLine);
    line["property"] = property;
    line["seed"] = seed;
    line["scalar"] = scalar;
    line["failure"] = failure;
    if (!extra.empty()) line.update(nlohmann::ordered_json::parse(extra));
    return line.dump();
}

}  // namespace tilesweep::properties
