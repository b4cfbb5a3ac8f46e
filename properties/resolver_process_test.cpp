// SPDX-License-Identifier: MIT
// The outside-resolver transport (resolver_process.h) against small shell resolvers: every
// scene gets its answer or its own failure, in pipe and in file mode, whatever the resolver does
// (crash, hang, extra lines), and kept answers are not asked for again.
#include "resolver_process.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tilesweep::properties {
namespace {

/// Scenes for the fake resolvers: their text says what the resolver does with them.
const std::vector<std::string> kScenes = {"first", "second", "crash", "fourth", "hang", "sixth"};

TEST(ResolverProcess, pipeModeAnswersOneLinePerSceneInOrder) {
    ResolverProcess process("while read -r line; do echo \"answer $line\"; done", 5);
    EXPECT_FALSE(process.fileMode());
    const std::vector<ResolverReply> replies = process.exchange({"a", "b", "c"});
    ASSERT_EQ(replies.size(), 3u);
    EXPECT_EQ(replies[0].line, "answer a");
    EXPECT_EQ(replies[2].line, "answer c");
    EXPECT_EQ(process.starts(), 1);
}

TEST(ResolverProcess, fileModeRunsTheCommandOncePerBatch) {
    ResolverProcess process("sed 's/^/answer /' {in} > {out}", 5);
    EXPECT_TRUE(process.fileMode());
    const std::vector<ResolverReply> replies = process.exchange({"a", "b", "c"});
    ASSERT_EQ(replies.size(), 3u);
    for (const ResolverReply& r : replies) EXPECT_TRUE(r.failure.empty()) << r.failure;
    EXPECT_EQ(replies[1].line, "answer b");
    EXPECT_EQ(process.starts(), 1);
}

TEST(ResolverProcess, fileModeCrashFailsOnlyTheSceneItCrashedOn) {
    // Answers line by line and exits with status 3 on "crash": the scene after it still gets
    // its answer from a fresh run.
    ResolverProcess process(
        "while read -r line; do [ \"$line\" = crash ] && { echo dying >&2; exit 3; }; echo \"ok $line\" >> "
        "{out}; "
        "done < {in}",
        5);
    const std::vector<ResolverReply> replies = process.exchange({"first", "crash", "third"});
    EXPECT_EQ(replies[0].line, "ok first");
    EXPECT_NE(replies[1].failure.find("exited with status 3"), std::string::npos) << replies[1].failure;
    EXPECT_NE(replies[1].failure.find("dying"), std::string::npos) << replies[1].failure;  // its output tail
    EXPECT_EQ(replies[2].line, "ok third");
    EXPECT_EQ(process.starts(), 2);
}

TEST(ResolverProcess, fileModeHangFailsOnlyTheSceneItHungOn) {
    ResolverProcess process(
        "while read -r line; do [ \"$line\" = hang ] && sleep 30; echo \"ok $line\" >> {out}; done < {in}",
        0.5);
    const std::vector<ResolverReply> replies = process.exchange({"first", "hang", "third"});
    EXPECT_EQ(replies[0].line, "ok first");
    EXPECT_NE(replies[1].failure.find("no answer within"), std::string::npos) << replies[1].failure;
    EXPECT_EQ(replies[2].line, "ok third");
}

TEST(ResolverProcess, pipeModeCrashAndHangFailOnlyTheirScenes) {
    ResolverProcess process(
        "while read -r line; do case $line in crash) exit 4;; hang) sleep 30;; esac; echo \"ok $line\"; done",
        0.5);
    const std::vector<ResolverReply> replies = process.exchange(kScenes);
    ASSERT_EQ(replies.size(), kScenes.size());
    EXPECT_EQ(replies[0].line, "ok first");
    EXPECT_NE(replies[2].failure.find("exited with status 4"), std::string::npos) << replies[2].failure;
    EXPECT_EQ(replies[3].line, "ok fourth");
    EXPECT_NE(replies[4].failure.find("no answer within"), std::string::npos) << replies[4].failure;
    EXPECT_EQ(replies[5].line, "ok sixth");
}

TEST(ResolverProcess, moreLinesThanScenesFailsTheLastScene) {
    ResolverProcess process("cat {in} {in} > {out}", 5);
    const std::vector<ResolverReply> replies = process.exchange({"a", "b"});
    EXPECT_EQ(replies[0].line, "a");
    EXPECT_NE(replies[1].failure.find("more lines"), std::string::npos) << replies[1].failure;
}

TEST(ResolverProcess, missingAnswerFileFailsEveryScene) {
    ResolverProcess process("true {in} {out}", 5);
    const std::vector<ResolverReply> replies = process.exchange({"a", "b"});
    for (const ResolverReply& r : replies)
        EXPECT_NE(r.failure.find("answering 0 of"), std::string::npos) << r.failure;
}

TEST(ResolverProcess, keptAnswersAreNotAskedForAgain) {
    ResolverProcess process("sed 's/^/answer /' {in} > {out}", 5);
    process.prefetch({"a", "b", "a", "c"});
    EXPECT_EQ(process.batchesSent(), 1u);
    EXPECT_EQ(process.scenesSent(), 3u);  // the duplicate once
    const std::vector<ResolverReply> kept = process.exchange({"c", "a"});
    EXPECT_EQ(kept[0].line, "answer c");
    EXPECT_EQ(kept[1].line, "answer a");
    EXPECT_EQ(process.batchesSent(), 1u);
    const std::vector<ResolverReply> fresh = process.exchange({"a", "d"});  // only d is sent
    EXPECT_EQ(fresh[1].line, "answer d");
    EXPECT_EQ(process.scenesSent(), 4u);
    process.clearKept();
    (void)process.exchange({"a"});
    EXPECT_EQ(process.scenesSent(), 5u);
}

}  // namespace
}  // namespace tilesweep::properties
