#pragma once
// A ball the user holds in a running simulation (Simulation::grab): it follows the straight path
// it is steered along, as a body of unlimited mass, pushing what it meets out of its way and
// sliding along what does not move. Its contacts are solved as any other's, so nothing passes
// through it; where a ball it pushes would be crushed against something, the grab stops.

namespace carom {

enum class GrabStopKind {
  // A ball pushed nearly head-on against something that does not give way, with less than its
  // radius left between (tolerance::kCrushRoomFraction, kCrushEscapeFactor).
  Crush,
  // The held ball kept meeting things without getting anywhere (kMaxCollisionsInBurst contacts,
  // each after a travel below kBurstTravelFraction of its radius): a jam of several balls.
  Jam,
};

struct GrabStop {
  GrabStopKind kind = GrabStopKind::Crush;
  int held = -1;   // the held ball
  int other = -1;  // the ball that would have been crushed, or -1
  double time = 0.0;
};

}  // namespace carom
