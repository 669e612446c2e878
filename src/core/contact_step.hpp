// One evaluation of the first-contact search: the clearance of a frame and the time no contact
// can happen in (the method is described in first_contact.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/motion.hpp"
#include "dragon/collision.hpp"

namespace dragon::contact {

inline constexpr double kMargin = 0.7;    // broad-phase margin, m
inline constexpr double kMaxTravel = 2.0; // m of head travel per step; keeps the bound's drift small
inline constexpr double kProbeGap = 2e-3; // m; below this clearance, try to bracket the contact

// What the stepper remembers of the near pairs at the last evaluation: the corner-gap rates and
// the curvature bound the step relied on, to check that bound against the rates found next.
struct PairMemory {
    double time;
    std::array<double, 8> rates;
    double curvature;
};
inline std::uint64_t key_of(int a, int b) { return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b); }

// The near pairs' memories by pair: a flat open-addressing table (a few hundred entries written
// and read per evaluation; a node-based map spent more time allocating than the bounds took).
class Memory {
public:
    const PairMemory* find(std::uint64_t key) const {
        if (slots_.empty()) return nullptr;
        for (size_t k = hash(key);; k = (k + 1) & mask()) {
            if (slots_[k].key == key) return &slots_[k].value;
            if (slots_[k].key == kEmpty) return nullptr;
        }
    }
    void emplace(std::uint64_t key, const PairMemory& value) {
        if (2 * (size_ + 1) > slots_.size()) grow();
        size_t k = hash(key);
        while (slots_[k].key != kEmpty && slots_[k].key != key) k = (k + 1) & mask();
        if (slots_[k].key == kEmpty) ++size_;
        slots_[k] = {key, value};
    }
    void clear() {
        for (Slot& s : slots_) s.key = kEmpty;
        size_ = 0;
    }
    void swap(Memory& other) noexcept {
        slots_.swap(other.slots_);
        std::swap(size_, other.size_);
    }
    template <class F>
    void for_each(F&& f) {
        for (Slot& s : slots_)
            if (s.key != kEmpty) f(s.value);
    }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    struct Slot {
        std::uint64_t key = kEmpty;
        PairMemory value{};
    };
    size_t mask() const { return slots_.size() - 1; }
    size_t hash(std::uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask(); }
    void grow() {
        std::vector<Slot> old(std::max<size_t>(64, 2 * slots_.size()));
        old.swap(slots_);
        size_ = 0;
        for (const Slot& s : old)
            if (s.key != kEmpty) emplace(s.key, s.value);
    }
    std::vector<Slot> slots_;
    size_t size_ = 0;
};

struct Approach {
    // The closest pair among those looked at: exact whenever the true clearance is below
    // kProbeGap (the pairs passed over are farther apart than that), else only an upper bound.
    Clearance clear;
    double safe_step;  // s: no contact can happen sooner
    double rate;       // d/dt of the closest pair's separation now (negative: closing)
    bool bound_broken; // a near pair's rates changed faster than the last step assumed
    // s: no pair but the closest one can touch sooner. A bracket for the closest pair's contact
    // must end by then, or the bisection in it could pass over another pair's brief contact.
    double others_step;
};

// What one search keeps between evaluations and reuses: the broad phase's order and arrays, and
// the per-pair arrays of an evaluation. One per worker of a search, never shared.
struct Workspace {
    BroadPhase broad;
    std::vector<BenchMotion> motion;
    std::vector<double> gaps, half_diagonals;
    std::vector<Radial> radial;
    struct Candidate {
        double first_order;
        double bound;
        size_t k;
    };
    std::vector<Candidate> tight;
    std::vector<std::pair<std::uint64_t, double>> pair_steps;
};

// `memory` is what the last accepted evaluation saw; this one's goes to `next` (cleared first),
// for the caller to keep if it accepts the step; `check` compares the two.
Approach approach(const Frame& f, double t, double max_step, const Memory& memory, Memory& next, bool check,
                  Workspace& ws);

}  // namespace dragon::contact
