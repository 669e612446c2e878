// One evaluation of the first-contact search: the clearance of a frame and the head travel no
// contact can happen in (the method is described in first_contact.cpp). The search runs on the
// motion at 1 m/s, so a frame's time is its head travel (m), and every speed and rate here is per
// metre of head travel.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "motion.hpp"
#include "swept_proof.hpp"
#include "dragon/constants.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"

namespace dragon::contact {

inline constexpr double kMargin = kBroadPhaseMargin;  // broad-phase margin, m
inline constexpr double kMaxTravel = 2.0; // m of head travel per step; keeps the bound's drift small
inline constexpr double kProbeGap = 2e-3; // m; below this clearance, try to bracket the contact

// What the stepper remembers of the near pairs at the last evaluation: the corner-gap rates and
// the curvature bound the step relied on, to check that bound against the rates found next.
struct PairMemory {
    double travel;  // m of head travel: where the rates were measured
    std::array<double, 8> rates;
    double curvature;
};
inline std::uint64_t key_of(int a, int b) { return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b); }

// What one evaluation promised of every broad-phase pair, for checking the step after it at its
// end: a lower bound on the pair's distance then, and the closing speed that bound's step took
// (the pair's first-order bound, or the radial one for a pair its radii keep apart).
struct GapRecord {
    double gap, closing;                // first order: projected gap, closing-speed bound (gap 0: none made)
    double radial_gap, radial_closing;  // from the radii (gap not positive: none)
    // The pair's step came from its second-order bound, whose curvature the next evaluation
    // checks on its own (refine_pairs), not from either first-order one.
    bool second_order = false;
};

// Records by pair: a flat open-addressing table (a few hundred entries written and read per
// evaluation; a node-based map spent more time allocating than the bounds took).
template <class Value>
class FlatMap {
public:
    Value* find(std::uint64_t key) { return const_cast<Value*>(static_cast<const FlatMap*>(this)->find(key)); }
    const Value* find(std::uint64_t key) const {
        if (slots_.empty()) return nullptr;
        for (size_t k = hash(key);; k = (k + 1) & mask()) {
            if (slots_[k].key == key) return &slots_[k].value;
            if (slots_[k].key == kEmpty) return nullptr;
        }
    }
    void emplace(std::uint64_t key, const Value& value) {
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
    void swap(FlatMap& other) noexcept {
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
        Value value{};
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
using Memory = FlatMap<PairMemory>;

// A group pair of far_pairs_step (contact_bounds.hpp) as one evaluation bounded it: the distance
// its members beyond the margin keep at least and their closing speed, and the gap their radii
// keep and the speed it closes at (not positive: none).
struct GroupRecord {
    double apart, closing;
    double radial_gap, radial_closing;
};

// Everything an evaluation promised, for checking at the next one: the near pairs' rates, every
// broad-phase pair's gap and closing speed, every group pair's.
struct StepRecord {
    double travel = 0.0;  // m of head travel: where the evaluation that promised was made
    Memory near;
    FlatMap<GapRecord> gaps;
    std::vector<GroupRecord> groups;
    void swap(StepRecord& other) noexcept {
        std::swap(travel, other.travel);
        near.swap(other.near);
        gaps.swap(other.gaps);
        groups.swap(other.groups);
    }
};

struct Approach {
    // The closest pair among those looked at: exact whenever the true clearance is below
    // kProbeGap (the pairs passed over are farther apart than that), else only an upper bound.
    Clearance clear;
    double safe_step;  // m of head travel: the rate bounds expect no contact sooner (the step's proof is swept_proof's)
    double rate;       // m/m: the closing pair's separation's derivative in head travel now (negative: closing)
    // The step that led here broke a promise of the last evaluation: a near pair's rates changed
    // faster than its curvature bound allowed, or a pair (or group of pairs, or two benches kept
    // apart by their radii) closes here faster than the gap it had there could take for the
    // whole step.
    bool bound_broken;
    // m of head travel: by the rate bounds, no pair but the closest one touches sooner. The probe
    // for the closest pair's contact stops there (the bracket it makes is then proved by
    // swept_proof before its contact is reported).
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
    Frame frame;  // a whole chain, solved for what the search keeps of it (the stretches' edges)
    SweptWorkspace swept;  // the steps' proofs (swept_proof.hpp)
    // How many times the closing rates measured at a step's start its steps allow for
    // (tol::rate_safety unless a test sets it): it chooses the steps' lengths only.
    double rate_safety = tol::rate_safety;
};

// Whether two non-adjacent benches of `f` overlap or touch, as the search's clearances (of
// approach() and of clearance(f, kMargin)) would say by a value <= 0, at a fraction of their
// cost (see contact_step.cpp): yes, no, or `unsure` when a pair is within kSureGap of touching
// but no projected gap is <= 0; the caller then asks the clearance itself. A search past the
// first contact starts overlapping and needs no more; a bisection needs only this sign.
inline constexpr double kSureGap = 1e-9;  // m: far above the rounding of a clearance, about 1e-15 m
enum class Overlap { yes, no, unsure };
Overlap overlap_of(const Frame& f, Workspace& ws);

// The evaluation of `f`, the chain at head travel `x` (m); `max_step` caps its step (m of head
// travel). `last` is what the last accepted evaluation promised; this one's goes to `next`
// (cleared first), for the caller to keep if it accepts the step; `check` holds this evaluation,
// the end of the step from `last`, to those promises.
Approach approach(const Frame& f, double x, double max_step, const StepRecord& last, StepRecord& next, bool check,
                  Workspace& ws);

}  // namespace dragon::contact
