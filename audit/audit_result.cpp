// SPDX-License-Identifier: MIT
// The audit's figures (audit.h): metric names, and cells, coverage and worst cases merged from the
// workers' shards.
#include "tilesweep/audit/audit.h"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace tilesweep::audit {

const char* metricName(Metric m) {
    switch (m) {
        case Metric::Decision:
            return "decision";
        case Metric::Inexact:
            return "inexact";
        case Metric::Tunnel:
            return "tunnel";
        case Metric::Inside:
            return "inside";
        case Metric::ClipMiss:
            return "clip-miss";
        case Metric::CornerHit:
            return "corner-hit";
        case Metric::Snag:
            return "snag";
        case Metric::NonFinite:
            return "non-finite";
        case Metric::Missed:
            return "missed-contact";
        case Metric::Extra:
            return "extra-contact";
        case Metric::Short:
            return "short";
        case Metric::Overshoot:
            return "overshoot";
        case Metric::NoAnswer:
            return "no-answer";
        case Metric::Position:
            return "position";
        case Metric::Time:
            return "time";
        case Metric::PlatformFall:
            return "platform-fall";
        case Metric::PlatformBlock:
            return "platform-block";
        case Metric::PlatformSnag:
            return "platform-snag";
    }
    return "?";
}

void WorstCase::merge(const WorstCase& other) {
    if (!other.found) return;
    if (!found || other.score > score || (other.score == score && other.caseIndex < caseIndex)) *this = other;
}

void CellStats::merge(const CellStats& other) {
    scenes += other.scenes;
    for (std::size_t m = 0; m < kMetricCount; ++m) {
        failures[m] += other.failures[m];
        worst[m].merge(other.worst[m]);
    }
    clipEligible += other.clipEligible;
    cornerEligible += other.cornerEligible;
    restingEligible += other.restingEligible;
    positionUlps.insert(positionUlps.end(), other.positionUlps.begin(), other.positionUlps.end());
    timeErrors.insert(timeErrors.end(), other.timeErrors.begin(), other.timeErrors.end());
    if (epsilonMismatches.size() < other.epsilonMismatches.size())
        epsilonMismatches.resize(other.epsilonMismatches.size());
    for (std::size_t k = 0; k < other.epsilonMismatches.size(); ++k)
        epsilonMismatches[k] += other.epsilonMismatches[k];
}

void Coverage::merge(const Coverage& o) {
    scenes += o.scenes;
    hit += o.hit;
    twoStep += o.twoStep;
    tie += o.tie;
    cornerClip += o.cornerClip;
    cornerMiss += o.cornerMiss;
    cornerPass += o.cornerPass;
    startOverlap += o.startOverlap;
    resting += o.resting;
    filtered += o.filtered;
    exactPath += o.exactPath;
}

const CellStats& AuditResult::cell(const std::string& implementation, const std::string& family) const {
    for (std::size_t r = 0; r < implementations.size(); ++r)
        if (implementations[r].name == implementation)
            for (std::size_t c = 0; c < families.size(); ++c)
                if (families[c].name == family) return cells[r][c];
    throw std::out_of_range("no audit cell " + implementation + " x " + family);
}

std::string smallestFixingEpsilon(const CellStats& cell) {
    for (std::size_t k = 0; k < cell.epsilonMismatches.size() && k < kSeedEpsilons.size(); ++k) {
        if (cell.epsilonMismatches[k] == 0 && cell.scenes > 0) {
            char text[32];
            std::snprintf(text, sizeof text, "%g", kSeedEpsilons[k]);
            return text;
        }
    }
    return "none";
}

}  // namespace tilesweep::audit
