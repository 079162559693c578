#pragma once
// What the simulation worker hands to the GUI: an immutable picture of one moment. The worker
// publishes a new one after each batch of steps; the GUI reads the latest without waiting.

#include "run_stats.h"
#include "scene.h"

#include <atomic>
#include <memory>
#include <vector>

namespace carom::ui {

struct SimulationSnapshot {
  double time = 0.0;
  std::vector<Vec3> positions;
  std::vector<Vec3> velocities;  // same order
  // Since the previous snapshot. A snapshot replaced before the GUI took it takes its collisions
  // with it: when the GUI falls behind, explosions and sounds are dropped, never delayed.
  std::vector<CollisionRecord> collisions;
  double kineticEnergy = 0.0;
  double potentialEnergy = 0.0;
  double initialEnergy = 0.0;  // at the last reset
  RunStats stats;
  World world;
  bool running = false;
  double realTimeFactor = 0.0;  // simulated seconds per real second, over the last batch
  bool fallingBehind = false;   // the physics could not keep up with the requested speed
};

// A single-slot mailbox: the writer swaps in a new snapshot, the reader takes the latest. Both
// sides only ever touch an atomic pointer, so neither waits for the other.
class SnapshotExchange {
 public:
  // Returns true when the reader has taken the previous snapshot, so it needs telling; while it
  // has not, newer snapshots simply replace the unread one and no notice piles up.
  bool publish(std::shared_ptr<const SimulationSnapshot> snapshot) {
    latest_.store(std::move(snapshot), std::memory_order_release);
    return !unread_.exchange(true);
  }
  // The newest snapshot, marking it read.
  std::shared_ptr<const SimulationSnapshot> take() {
    unread_.store(false);
    return latest();
  }
  std::shared_ptr<const SimulationSnapshot> latest() const {
    return latest_.load(std::memory_order_acquire);
  }

 private:
  std::atomic<std::shared_ptr<const SimulationSnapshot>> latest_;
  std::atomic<bool> unread_{false};
};

}  // namespace carom::ui
