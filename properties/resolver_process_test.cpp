// SPDX-License-Identifier: MIT
// The outside-resolver transport (resolver_process.h) against small shell resolvers: every
// scene gets its answer or a failure, in pipe and in file mode, whatever the resolver does
// (crash, hang, extra lines), and kept answers are not asked for again.
#include "resolver_process.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace tilesweep::properties {
namespace {

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

TEST(ResolverProcess, fileModeHangFailsTheRestOfItsBatchAndTheNextBatchIsAnswered) {
    ResolverProcess process(
        "while read -r line; do [ \"$line\" = hang ] && sleep 30; echo \"ok $line\" >> {out}; done < {in}",
        0.5);
    std::vector<std::string> failures;
    process.onFailure([&](const std::string& why) { failures.push_back(why); });
    const std::vector<ResolverReply> replies = process.exchange({"first", "hang", "third"});
    EXPECT_EQ(replies[0].line, "ok first");
    EXPECT_NE(replies[1].failure.find("no answer within 0.5 s"), std::string::npos) << replies[1].failure;
    EXPECT_NE(replies[2].failure.find("hung on scene 2 of its batch"), std::string::npos)
        << replies[2].failure;
    ASSERT_EQ(failures.size(), 1u);  // one hang, told once
    EXPECT_EQ(failures[0], replies[1].failure);
    const std::vector<ResolverReply> next = process.exchange({"fourth"});
    EXPECT_EQ(next[0].line, "ok fourth");
}

TEST(ResolverProcess, pipeModeCrashFailsItsSceneAndHangTheRestOfItsBatch) {
    // A crash costs one scene and a restart; a hang costs one timeout for the whole batch, not
    // one a scene.
    ResolverProcess process(
        "while read -r line; do case $line in crash) exit 4;; hang) sleep 30;; esac; echo \"ok $line\"; done",
        0.5);
    std::vector<std::string> failures;
    process.onFailure([&](const std::string& why) { failures.push_back(why); });
    const std::vector<ResolverReply> replies =
        process.exchange({"first", "second", "crash", "fourth", "hang", "sixth", "seventh"});
    ASSERT_EQ(replies.size(), 7u);
    EXPECT_EQ(replies[0].line, "ok first");
    EXPECT_NE(replies[2].failure.find("exited with status 4"), std::string::npos) << replies[2].failure;
    EXPECT_EQ(replies[3].line, "ok fourth");
    EXPECT_NE(replies[4].failure.find("no answer within"), std::string::npos) << replies[4].failure;
    EXPECT_NE(replies[4].failure.find("after answering 1 of the 4 scenes sent"), std::string::npos)
        << replies[4].failure;
    for (std::size_t k = 5; k < 7; ++k)
        EXPECT_NE(replies[k].failure.find("hung on scene 5 of its batch"), std::string::npos)
            << replies[k].failure;
    EXPECT_EQ(failures.size(), 2u);  // the crash and the hang
    const std::vector<ResolverReply> next = process.exchange({"eighth"});
    EXPECT_EQ(next[0].line, "ok eighth");
    EXPECT_EQ(process.starts(), 3);
}

TEST(ResolverProcess, killLiveResolverProcessesEndsWhatTheResolverStarted) {
    // The shell and the sleep it started are one process group; killing it ends both, so a
    // worker stopped by a signal leaves nothing behind.
    ResolverProcess process("sleep 30 & wait", 5);
    std::vector<ResolverReply> replies;
    std::thread killer([] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        killLiveResolverProcesses();
    });
    const auto began = std::chrono::steady_clock::now();
    replies = process.exchange({"a"});
    killer.join();
    EXPECT_LT(std::chrono::steady_clock::now() - began, std::chrono::seconds(3));
    EXPECT_NE(replies[0].failure.find("killed by signal 9"), std::string::npos) << replies[0].failure;
}

TEST(ResolverProcess, moreLinesThanScenesFailsTheLastScene) {
    ResolverProcess process("cat {in} {in} > {out}", 5);
    const std::vector<ResolverReply> replies = process.exchange({"a", "b"});
    EXPECT_EQ(replies[0].line, "a");
    EXPECT_NE(replies[1].failure.find("more lines"), std::string::npos) << replies[1].failure;
}

TEST(ResolverProcess, aStrayLineFailsItsSceneEveryTimeWhereverItIsPrinted) {
    // "stray" prints a line before its answer, "late" one after it: without a barrier the late
    // one arrives after the batch has been judged, and is caught only when it happens to come in
    // time. With one, both are that scene's failure in every batch, and the others are answered.
    ResolverProcess process(
        "while read -r line; do [ \"$line\" = stray ] && echo junk; echo \"ok $line\"; "
        "[ \"$line\" = late ] && { sleep 0.05; echo late-junk; }; done",
        5);
    process.setBarrier("barrier");
    for (int round = 0; round < 3; ++round) {
        const std::vector<ResolverReply> replies = process.exchange({"a", "stray", "c", "late"});
        ASSERT_EQ(replies.size(), 4u);
        EXPECT_EQ(replies[0].line, "ok a") << replies[0].failure;
        EXPECT_NE(replies[1].failure.find("more than one line for this scene"), std::string::npos)
            << replies[1].failure << replies[1].line;
        EXPECT_EQ(replies[2].line, "ok c") << replies[2].failure;
        EXPECT_NE(replies[3].failure.find("more than one line for this scene"), std::string::npos)
            << replies[3].failure << replies[3].line;
        const std::vector<ResolverReply> clean = process.exchange({"d"});
        EXPECT_EQ(clean[0].line, "ok d") << clean[0].failure;
    }
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
