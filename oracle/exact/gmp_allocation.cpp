// SPDX-License-Identifier: MIT
#include "tilesweep/oracle/exact/gmp_allocation.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <gmp.h>

namespace tilesweep::oracle {

namespace {

// Every block given to GMP sits after a header of kHeaderBytes that holds its size class: c in
// [1, kClasses] for a cached block of c * kGranule bytes, 0 for a larger block malloc'd for its
// own size. Frees and reallocations read the class from the header, never from the sizes GMP
// passes, so a wrong size can neither put a block in the wrong list nor overrun one. The header
// is 16 bytes, so a block keeps malloc's 16-byte alignment.
constexpr std::size_t kHeaderBytes = 16;
constexpr std::size_t kGranule = 16;
constexpr std::size_t kClasses = 32;  // cached blocks hold up to 512 bytes
// Freed blocks a thread keeps per class; the rest go back to free. The exact reference keeps a
// few dozen numbers alive at once, so its blocks cycle through far fewer than this.
constexpr std::size_t kKeptPerClass = 1024;

struct Header {
    std::size_t sizeClass;
    std::size_t padding;
};
static_assert(sizeof(Header) == kHeaderBytes);

/// A cached block, linked through its header's first word.
struct FreeBlock {
    FreeBlock* next;
};
static_assert(sizeof(FreeBlock) <= kHeaderBytes);

struct ThreadCache {
    FreeBlock* head[kClasses + 1] = {};
    std::size_t kept[kClasses + 1] = {};
    ~ThreadCache();
};

// Whether this thread's cache is gone: set at thread exit, and on the main thread before the
// static objects are destroyed, which may still free numbers. A bool has no destructor, so it
// can be read then; with it set, blocks go straight back to free.
thread_local bool tCacheGone = false;
thread_local ThreadCache tCache;

ThreadCache::~ThreadCache() {
    tCacheGone = true;
    for (std::size_t c = 1; c <= kClasses; ++c)
        while (head[c] != nullptr) {
            FreeBlock* block = head[c];
            head[c] = block->next;
            std::free(block);
        }
}

[[noreturn]] void outOfMemory(std::size_t bytes) noexcept {
    std::fprintf(stderr, "tilesweep: out of memory for an exact number (%zu bytes)\n", bytes);
    std::abort();
}

/// The class of a block of `bytes`: the granules it needs, at least 1 (0 is "not cached").
std::size_t classOf(std::size_t bytes) noexcept {
    return std::max<std::size_t>((bytes + kGranule - 1) / kGranule, 1);
}

Header* headerOf(void* block) noexcept {
    return reinterpret_cast<Header*>(static_cast<unsigned char*>(block) - kHeaderBytes);
}

void* blockAfter(void* base, std::size_t sizeClass) noexcept {
    static_cast<Header*>(base)->sizeClass = sizeClass;
    return static_cast<unsigned char*>(base) + kHeaderBytes;
}

void* allocate(std::size_t bytes) {
    const std::size_t c = classOf(bytes);
    if (c > kClasses) {
        void* base = std::malloc(kHeaderBytes + bytes);
        if (base == nullptr) outOfMemory(bytes);
        return blockAfter(base, 0);
    }
    if (!tCacheGone && tCache.head[c] != nullptr) {
        FreeBlock* block = tCache.head[c];
        tCache.head[c] = block->next;
        --tCache.kept[c];
        return blockAfter(block, c);
    }
    void* base = std::malloc(kHeaderBytes + c * kGranule);
    if (base == nullptr) outOfMemory(bytes);
    return blockAfter(base, c);
}

void release(void* block, std::size_t /*bytes: the header says*/) {
    Header* header = headerOf(block);
    const std::size_t c = header->sizeClass;
    if (c != 0 && !tCacheGone && tCache.kept[c] < kKeptPerClass) {
        auto* cached = reinterpret_cast<FreeBlock*>(header);
        cached->next = tCache.head[c];
        tCache.head[c] = cached;
        ++tCache.kept[c];
        return;
    }
    std::free(header);
}

void* reallocate(void* block, std::size_t oldBytes, std::size_t newBytes) {
    Header* header = headerOf(block);
    const std::size_t c = header->sizeClass;
    if (c != 0 && newBytes <= c * kGranule) return block;  // it still fits
    if (c == 0 && classOf(newBytes) > kClasses) {
        void* base = std::realloc(header, kHeaderBytes + newBytes);
        if (base == nullptr) outOfMemory(newBytes);
        return static_cast<unsigned char*>(base) + kHeaderBytes;  // the header still says 0
    }
    void* moved = allocate(newBytes);
    // A cached block holds c * kGranule bytes, whatever GMP says it held.
    const std::size_t held = c != 0 ? std::min(oldBytes, c * kGranule) : oldBytes;
    std::memcpy(moved, block, std::min(held, newBytes));
    release(block, oldBytes);
    return moved;
}

}  // namespace

void useCachedGmpAllocation() noexcept {
    static std::atomic<bool> done{false};
    if (done.exchange(true)) return;
    mp_set_memory_functions(allocate, reallocate, release);
}

}  // namespace tilesweep::oracle
