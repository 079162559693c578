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
  std::vector<CollisionRecord> collisions;  // since the previous snapshot
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
  void publish(std::shared_ptr<const SimulationSnapshot> snapshot) {
    latest_.store(std::move(snapshot), std::memory_order_release);
  }
  std::shared_ptr<const SimulationSnapshot> latest() const {
    return latest_.load(std::memory_order_acquire);
  }

 private:
  std::atomic<std::shared_ptr<const SimulationSnapshot>> latest_;
};

}  // namespace carom::ui
