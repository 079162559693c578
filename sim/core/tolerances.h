#pragma once
// Every tolerance and limit of the physics, named once. Lengths are relative to the balls'
// radii and speeds derive from gravity, so the solver behaves the same at any scale.

#include <cstddef>
#include <cstdint>

namespace carom::tolerance {

// Two shapes closer than this fraction of the relevant radius (sum) count as touching: allowed
// at the start of a run, and used to find the supports of a ball that comes to rest.
inline constexpr double kTouchFraction = 1e-9;

// A ball touching a part whose speed along the contact normal is within this fraction of its
// speed moves along the part by round-off, and the sign of that speed says nothing. On a flat
// face (a box's, a capped cylinder's cap) it meets the face at once when its acceleration presses
// it in and it would sink deeper than touching before it passes the face's edge; on a rounded part
// (an edge, a corner, a cylinder's side) the next term of the gap decides: its speed across the
// normal against the acceleration into the part. A response along a line of centres parallel to a
// face (two balls lying on a box's slope) leaves rates of up to 3e-14 of the speed, which the face
// took for a departure: the pressed ball sank into the box, a radius deep in 2 s (test_rest,
// test_boxes); a ball sliding off a turned box's lower edge arrives with 1e-17, which the edge took
// for an approach again and again, until the burst guard stopped the ball on the edge (test_boxes).
inline constexpr double kTangentRateFraction = 1e-12;

// A bounce lower than this fraction of the ball's radius is not resolved as a bounce: the
// contact becomes resting (see docs/physics.md, "Resting contact").
inline constexpr double kRestHeightFraction = 1e-3;

// A supported ball slower than this many rest speeds comes to rest, and a resting ball wakes
// only when hit faster than that: a ball hopping at the rest speed (rule 1 of rest_policy.h)
// settles, and does not wake its neighbours.
inline constexpr double kSettleSpeedFactor = 2.0;

// Gap (as a fraction of the radius) within which a slow ball's contacts count when deciding
// whether it can be put to rest: the height of the rest-speed hops. The contacts that carry
// its weight must also be closable together by a move no longer than this (a ball between
// walls meeting far below it is not supported; test_rest).
inline constexpr double kSupportGapFraction = 1e-2;

// Without gravity there is no rest speed from a bounce height; collisions slower than this
// fraction of the scene's initial RMS speed separate at that speed, which stops inelastic
// collapse in a free gas from taking ever shorter steps.
inline constexpr double kCollapseSpeedFraction = 1e-7;

// Scene limits: values beyond these are refused by validation as absurd.
inline constexpr double kMaxMagnitude = 1e12;
inline constexpr double kMinRadius = 1e-12;
inline constexpr double kMinMass = 1e-30;
inline constexpr double kMaxMass = 1e30;
inline constexpr double kMinTimeStep = 1e-12;
inline constexpr double kMaxTimeStep = 1e6;
// Friction coefficients (sliding, rolling, spinning): real materials stay below a few, and one
// of 1e6 already holds every contact as if glued.
inline constexpr double kMaxFriction = 1e6;
inline constexpr double kMinDirectionLength = 1e-100;
inline constexpr std::size_t kMaxBalls = 1'000'000;
inline constexpr std::size_t kMaxPlanes = 10'000;
inline constexpr std::size_t kMaxCylinders = 10'000;
inline constexpr std::size_t kMaxBoxes = 10'000;
// Characters (Unicode code points) of an object's name. A name is a label (the outline, the
// Ball story's legend, messages): 256 holds any a user would type, and bounds what showing one
// costs; Qt Charts' legend shortens a name in memory growing with its square, and a ball named
// with 30,000 characters took the window 1 GB when selected (docs/scene-format.md).
inline constexpr std::size_t kMaxNameCharacters = 256;

}  // namespace carom::tolerance

namespace carom::tolerance {

// Contacts hold a ball (or a cluster of balls) when pushes at them balance gravity on each ball
// to within this fraction of its weight: round-off of the solve. A ramp of 1e-6 rad
// is not level (test_rest).
inline constexpr double kForceBalance = 1e-12;
// `discrete` resolves each step's overlaps in up to this many passes, each looking again at the
// balls the one before pushed out of two overlaps or more: a column of touching balls on a
// floor needs about one pass a ball to push out (test_rest), a gas one or two.
inline constexpr int kMaxOverlapPasses = 32;

// The most balls whose contact forces are solved together when a ball comes to rest on others
// (its cluster, breadth first); balls further away count as fixed. Piles wider than this rest
// on their outer balls as on walls.
inline constexpr int kMaxClusterBalls = 8;

// A ball that takes part in more surface collisions than this in a row, each within a negligible
// flight of the last, is put to rest: the last guard against a cycle of contacts that lets time
// advance by mere round-off (a ball wedged between shapes).
inline constexpr int kMaxCollisionsInBurst = 64;
// A flight is negligible when the ball, at its speed when it arrives, travelled no further than
// touching distance (kTouchFraction of its radius). It acts on a ball jammed in a gap no wider
// than that (test_rest), and not on a ball of any speed that crosses its container (tested up
// to 1e10 m/s) or bounces down a wedge.
inline constexpr double kBurstTravelFraction = kTouchFraction;
// A ball touching several static shapes at once reflects off them in one event, at most this
// many times (a wedge of angle θ takes about π/θ; see EventEngine::leaveTouchingStatics).
inline constexpr long kMaxSimultaneousReflections = 10'000'000;
// Two elastic planes that reflect a ball more than this many times at one instant (a V narrower
// than about π/64 rad) are solved in closed form instead (reflectInWedge, response.h), whatever
// their angle; fewer keep the loop, whose arithmetic shallower creases have always had.
inline constexpr std::uint64_t kLoopReflections = 64;

// A held ball (grab.h) pushing a ball nearly head-on into something that does not give way
// would squeeze it ever faster (an unlimited mass closing a gap) and at last through: the grab
// stops when the pushed ball would have to move more than kCrushEscapeFactor times the push's
// speed to slip out sideways (the push within 30 degrees of head-on) and has less than
// kCrushRoomFraction of its radius left along the push (test_grab).
inline constexpr double kCrushEscapeFactor = 2.0;
inline constexpr double kCrushRoomFraction = 1.0;

// A ball on a face rolls when its slip (the contact point's velocity) is below this fraction of
// |v| + r·|ω| (v along the face, all of ω: the spin about the normal rounds into the part along
// the face too): the round-off of v - r·ω×n. A phase that ends in rolling sets the slip to zero
// exactly, so this acts only on states an impact or a method change handed over
// (test_friction).
inline constexpr double kRollingSlipFraction = 1e-12;
// A slide whose slip runs across the fall line of a tilted face, or a roll with resistance
// across it, turns as it goes and has no polynomial path. Its state is a closed form
// (TurningFacePath); the contact solvers take a parabola in its place, one segment at a time,
// each short enough that the two stay within this fraction of the ball's radius, a tenth of
// touching (kTouchFraction): a contact is found within that of touching, and only a graze
// shallower than it can be missed (test_friction). Never below four ulps of the ball's position,
// which no contact time resolves either.
inline constexpr double kTurningPathDeviation = 1e-10;

}  // namespace carom::tolerance
