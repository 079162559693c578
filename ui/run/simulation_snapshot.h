#pragma once
// What the simulation worker hands to the GUI: an immutable picture of one moment. The worker
// publishes a new one after each batch of steps; the GUI reads the latest without waiting.

#include "sim/dynamics/grab.h"
#include "sim/dynamics/run_stats.h"
#include "sim/measure/run_watch.h"
#include "sim/model/scene.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace carom::ui {

struct SimulationSnapshot {
  std::uint64_t startNumber = 0;  // which start the run began from (RunSession)
  double time = 0.0;
  std::vector<Vec3> positions;
  std::vector<Vec3> velocities;  // same order
  std::vector<Vec3> angularVelocities;
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
  // The timeline (sim/run_recording.h).
  std::uint64_t frame = 0;       // the frame shown
  std::uint64_t frameCount = 0;  // the frames recorded: the live run's present
  double latestTime = 0.0;       // the simulated time of the newest frame recorded
  std::size_t recordingBytes = 0;
  std::size_t keyframes = 0;
  double scrubMilliseconds = 0.0;  // what reproducing the frame shown took, when it was
  // Grabbing (sim/grab.h).
  int grabbed = -1;
  std::optional<GrabStop> grabStop;  // why the grab stopped, while it lasts
  bool throwCapped = false;          // the last throw was cut to the throw limit
  // The run watch's latest event and how many there have been since the worker started. Every
  // later snapshot carries them too, so that an event is not lost with a snapshot the GUI never
  // took: the GUI shows an event when the count has changed. The worker paused on it.
  std::optional<WatchEvent> watchEvent;
  std::uint64_t watchEvents = 0;
};

// A single-slot mailbox: the writer swaps in a new snapshot, the reader takes the latest. The
// lock is held only to copy or swap a pointer (never while a snapshot is built, read or freed),
// so neither side waits for the other's work. (libstdc++'s std::atomic<std::shared_ptr> is not
// lock-free either: it spins on a lock bit, which ThreadSanitizer cannot see as a lock.)
class SnapshotExchange {
 public:
  // Returns true when the reader has taken the previous snapshot, so it needs telling; while it
  // has not, newer snapshots simply replace the unread one and no notice piles up.
  bool publish(std::shared_ptr<const SimulationSnapshot> snapshot) {
    bool notify;
    {
      std::lock_guard lock(mutex_);
      latest_.swap(snapshot);
      notify = !unread_;
      unread_ = true;
    }
    return notify;  // the snapshot replaced goes with `snapshot`, outside the lock
  }
  // The newest snapshot, marking it read.
  std::shared_ptr<const SimulationSnapshot> take() {
    std::lock_guard lock(mutex_);
    unread_ = false;
    return latest_;
  }
  std::shared_ptr<const SimulationSnapshot> latest() const {
    std::lock_guard lock(mutex_);
    return latest_;
  }

 private:
  mutable std::mutex mutex_;
  std::shared_ptr<const SimulationSnapshot> latest_;  // guarded by mutex_
  bool unread_ = false;                               // guarded by mutex_
};

}  // namespace carom::ui
