#pragma once
// The earliest-contact-first loop shared by the `exact` and `swept` methods: every ball carries
// one predicted event (a contact or a move to the next grid cell) in the event queue; the
// earliest is processed, only the balls it changed are predicted again, and predictions that
// involved a ball changed since are dropped when their time comes (collision counters).
//
// Its parts: the cells, which find a ball's neighbours and the static shapes near it (CellLevels,
// the broad phase); the contacts' responses (engine_contacts.cpp); the surfaces a ball may slide
// on (SlideSurfaces) and the sliding itself with friction's phases on faces (engine_sliding.cpp,
// face_friction.h); the rest decisions (RestCheck, engine_resting.cpp); `swept`'s energy books
// (EnergyBooks); the held ball (HeldBall, engine_grab.cpp).
//
// Balls move lazily: each keeps its path from the time it last changed, so an event costs
// O(neighbours + log N), not O(N).

#include "sim/core/tolerances.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/face_friction.h"
#include "sim/dynamics/grab.h"
#include "sim/dynamics/run_stats.h"
#include "sim/dynamics/turning_face_path.h"
#include "sim/exact/cell_levels.h"
#include "sim/exact/energy_books.h"
#include "sim/exact/event_queue.h"
#include "sim/exact/held_ball.h"
#include "sim/exact/slide_surfaces.h"
#include "sim/exact/static_ref.h"
#include "sim/geometry/contact_time.h"
#include "sim/geometry/motion.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace carom {

class RestCheck;

class EventEngine {
 public:
  // `pathAcceleration` is what balls follow between events: gravity for `exact`, zero for the
  // straight sweeps of `swept`. `gravity` drives the rest policy in both. `stepSpeed` is the
  // speed one time step's kick of gravity gives under `swept` (0 for `exact`): a contact no
  // faster than that is as slow as a stepped method can tell, and counts as a resting one.
  EventEngine(const Bodies& bodies, const std::vector<BallState>& state, double now,
              const Vec3& gravity, const Vec3& pathAcceleration, double collapseSpeed,
              double stepSpeed = 0.0);

  // Processes every event up to and including time `end`, then stands at `end`.
  void advanceTo(double end, RunStats& stats, std::vector<CollisionRecord>* log);

  double now() const { return now_; }
  int ballCount() const { return static_cast<int>(particles_.size()); }
  // The grid in use, for run reports ("cell grid 20x20x20, 8000 cells").
  std::string gridSummary() const { return cells_.summary(); }
  BallState stateOf(int ball) const;
  std::vector<BallState> state() const;

  // Events after `time` need not be predicted (the end of a swept step): they are left out,
  // which saves work; they are found when the engine is told about the next step.
  void setHorizon(double time) { horizon_ = time; }

  // Replaces every ball's velocity at now() (for the integrator kicks of `swept`) and predicts
  // all events again. The held ball keeps its own; a resting one stays, its velocity only the
  // kick that its support holds (which spinning friction measures, spinInPlace).
  void setVelocities(const std::vector<Vec3>& velocities);

  // The held ball (grab.h, Stepper::hold).
  void hold(int i, const Vec3& velocity, RunStats& stats);
  void release(const Vec3& velocity);
  void place(const Vec3& position);
  int held() const { return held_.ball(); }
  std::optional<GrabStop> takeGrabStop() { return held_.takeStop(); }

  // The memory the engine holds, in bytes.
  std::size_t memoryBytes() const;

 private:
  // Rule 3 of the rest policy, a question about the balls as they are (rest_check.h).
  friend class RestCheck;

  // SlideEnd: a ball sliding on a box's face or a capped cylinder's cap reaches its edge or rim.
  // PhaseEnd: a ball on a face with friction ends its phase (face_friction.h).
  enum class EventKind : std::uint8_t { None, Ball, Plane, Cylinder, Box, SlideEnd, PhaseEnd };
  // What a neighbour search reads of every ball, in one cache line.
  struct alignas(64) Track {
    Motion motion;
    double radius;
  };
  // A ball's state beside its path (its cell is the CellLevels').
  struct Particle {
    std::uint32_t counter = 0;  // changes whenever the path changes
    int collisionsInBurst = 0;
    double lastSurfaceCollision = -std::numeric_limits<double>::infinity();
    // Its lasting contact with flat faces (engine_sliding.cpp): the slide on one surface or along
    // the crease of two; with friction, the phase on the surface is in faces_.
    int slidePlane = -1;   // the surface (slides_) the ball slides on, or -1 in flight
    int creasePlane = -1;  // a second one, when it slides along the crease of the two
    bool resting = false;
    // Put to rest by the burst guard: held in its wedge, it is not loosened (RestCheck).
    bool wedged = false;
    // It left a wedge at the end of its last burst (leaveWedge), and has not flown since.
    bool leftWedge = false;
    bool held = false;  // the held ball (grab.h)
  };
  // A ball's earliest predicted contact, kept apart from its next cell crossing so that a
  // crossing, which leaves the path alone, need not predict the contact again.
  struct Contact {
    double time = std::numeric_limits<double>::infinity();  // absolute
    EventKind kind = EventKind::None;
    int other = -1;
    std::uint32_t otherCounter = 0;  // the partner ball's counter when predicted
  };

  // The balls' paths.
  BallPath pathAt(int i, double t) const;
  const Vec3& accelerationOf(int i) const {
    // Without path acceleration nobody's flag need be read (a cache miss in the hot loop).
    if (straightPaths_) return zero_;
    const Particle& p = particles_[i];
    if (p.resting || p.held) return zero_;
    if (p.slidePlane < 0) return pathAcceleration_;
    if (p.creasePlane >= 0) return creaseAcceleration_[i];
    return roughFaces_ ? faces_[i].motion.acceleration : slides_.acceleration(p.slidePlane);
  }
  // Ball i's angular velocity at time t (no earlier than its path's start).
  Vec3 spinAt(int i, double t) const {
    if (!roughFaces_) return spin_[i];
    const FaceContact& f = faces_[i];
    const Vec3 w = SpinPath{spin_[i], f.motion.angularAcceleration, f.normal, f.normalDecay,
                            tracks_[i].motion.since}
                       .at(t);
    if (!f.motion.turning) return w;
    // Along the face the closed form's; about the normal spinning friction's.
    return w.dot(f.normal) * f.normal + turningFaces_[i].at(t).spinAlong;
  }
  // What gravity does to ball i's velocity, whichever path it follows: the rest policy's view
  // (a pair that gravity presses together), the same under `exact` and `swept`.
  Vec3 gravityOn(int i) const {
    const Particle& p = particles_[i];
    if (p.resting || p.held) return Vec3::Zero();
    if (p.slidePlane < 0) return gravity_;
    if (p.creasePlane < 0) return slides_.gravity(p.slidePlane);
    return gravity_.dot(creaseLine_[i]) * creaseLine_[i];
  }
  // Whether acceleration `a` presses along unit normal n by more than the round-off of a normal
  // between two centres (kTangentRateFraction of |a|): two balls side by side on a floor meet
  // along a normal whose vertical part is round-off, and its sign must not decide rule 1.
  static bool pressesAlong(const Vec3& a, const Vec3& n) {
    return a.dot(n) > tolerance::kTangentRateFraction * a.norm();
  }
  void moveTo(int i, double t) {
    if (roughFaces_) spin_[i] = spinAt(i, t);
    tracks_[i].motion.moveTo(t, accelerationOf(i));
    // A turning path's parabola only stands in for it in the contact solvers: the state is the
    // closed form's.
    if (roughFaces_ && faces_[i].motion.turning) {
      const TurningFacePath::State exact = turningFaces_[i].at(t);
      tracks_[i].motion.position = turningFaces_[i].from + exact.displacement;
      tracks_[i].motion.velocity = exact.velocity;
    }
    if (particles_[i].slidePlane >= 0) keepOnPlane(i);
  }
  void changed(int i);

  // The loop (event_engine.cpp): predictions, crossings and events.
  // Each ball's position now, for building the cells.
  std::vector<Vec3> positions() const;
  // Builds the cells again when they are crowded (CellLevels::crowded).
  void rebuildCellsIfCrowded();
  void predictAll();
  // Predicts ball i's next contact and crossing from scratch.
  void predict(int i);
  // The earliest contact with a static shape, solved for no further ahead than `until`.
  void findStaticContact(int i, const BallPath& path,
                         double until = std::numeric_limits<double>::infinity());
  void findBallContact(int i, const BallPath& path, int k);
  // Tests every ball that forEachBall(visit) visits.
  template <typename ForEachBall>
  void findBallContacts(int i, const BallPath& path, ForEachBall&& forEachBall);
  void schedule(int i);
  void cross(int i, RunStats& stats);
  // After ball i came to rest: a resting ball has no event of its own, so balls about to hit
  // it must be told.
  void warnNeighbours(int i);
  void process(int i, RunStats& stats, std::vector<CollisionRecord>* log);
  template <typename F>
  void forEachNeighbour(int i, F&& f) const {
    cells_.forEachNeighbour(i, f);
  }

  // Contacts (engine_contacts.cpp).
  // Ball i (at `position`, by default its last stored one) against a plane or cylinder: the unit
  // normal towards the ball, the gap between their surfaces and the contact's restitution.
  struct StaticContact {
    Vec3 normal;
    double gap;
    double restitution;
  };
  static StaticKind staticKindOf(EventKind kind) {
    return kind == EventKind::Box        ? StaticKind::Box
           : kind == EventKind::Cylinder ? StaticKind::Cylinder
                                         : StaticKind::Plane;
  }
  StaticContact staticContact(int i, StaticRef ref, const Vec3& position) const;
  StaticContact staticContact(int i, StaticRef ref) const {
    return staticContact(i, ref, tracks_[i].motion.position);
  }
  // The contact's restitution of ball i with a static shape.
  double restitutionWith(int i, StaticRef ref) const;
  // A contact with a static shape now; `face` is the slide surface it may slide on, or -1.
  void collideWithStatic(int i, StaticRef ref, int face, RunStats& stats,
                         std::vector<CollisionRecord>* log);
  void collideBalls(int i, int j, RunStats& stats, std::vector<CollisionRecord>* log);
  // The least separation speed of balls i and j meeting along unit normal n (from i to j), and
  // the approach below which restitution takes nothing (rules 1 and 8 of rest_policy.h): a
  // pair that gravity presses together parts at no less than the rest speed (an elastic one
  // at the slide speed), and any pair faster than round-off in its velocities.
  struct PairFloor {
    double minimum;
    double lossless;
  };
  PairFloor pairFloor(int i, int j, const Vec3& n, double restitution) const;
  // Ball i meets something that does not move (plane, cylinder, resting ball) along unit normal
  // n pointing to the ball.
  // `plane` is the plane's index when the surface is one: a slow enough contact with a plane
  // that gravity presses the ball against turns into sliding along it.
  // `law` is the impact's friction (none: frictionless).
  void collideWithSurface(int i, const Vec3& n, double restitution, RunStats& stats, int plane = -1,
                          const ImpactFriction& law = {});
  // The same contact when it does not end in rest.
  void bounceOffSurface(int i, const Vec3& n, double restitution, RunStats& stats, int plane = -1,
                        const ImpactFriction& law = {});
  // The friction of ball i's impacts with static shape `ref`.
  ImpactFriction impactFrictionWith(int i, StaticRef ref) const;
  void leaveTouchingStatics(int i, RunStats& stats);
  // Ball i in a burst of contacts with negligible flights between: whether it leaves the
  // shapes around it at once, reflected off them all (engine_contacts.cpp).
  bool leaveWedge(int i, RunStats& stats);
  void notePenetration(double overlap, RunStats& stats) const;

  // Sliding (engine_sliding.cpp; docs/physics.md, "Sliding"): the ball keeps touching the plane and
  // follows gravity's component along it, an exact path, until a contact sends it off faster than a
  // bounce of round-off height.
  void startSliding(int i, int plane);
  // What a slow contact of ball i with pressing plane `plane` becomes: kAlone (a slide on it),
  // another plane's index (a slide along their crease), or kNoCapture (a bounce).
  static constexpr int kAlone = -1;
  static constexpr int kNoCapture = -2;
  int slideCapture(int i, int plane) const;
  void startCrease(int i, int plane);
  // Lets go of the planes that ball i's velocity leaves faster than the slide speed.
  void dropPlanesLeft(int i);
  // Whether ball p slides along `ref` (and so never into it).
  bool slidesAgainst(const Particle& p, StaticRef ref) const {
    return (p.slidePlane >= 0 && slides_.holds(ref, p.slidePlane)) ||
           (p.creasePlane >= 0 && slides_.holds(ref, p.creasePlane));
  }
  // When ball i, sliding on a box's face or a cap, reaches the face's edge or the cap's rim.
  void findSlideEnd(int i, const BallPath& path);
  // The slide's end: past the edge or rim the ball flies, or meets the shape at once when it
  // would fly into the rounding there (SlideSurfaces::bendsIntoEnd).
  void endSlide(int i, RunStats& stats, std::vector<CollisionRecord>* log);
  // After ball i's velocity changed: a sliding ball pushed into its plane bounces off it, and
  // one that now leaves it flies.
  void updateSlide(int i, RunStats& stats);
  // Puts a sliding ball back on its plane exactly, undoing round-off drift off it.
  void keepOnPlane(int i);
  // Friction on faces (engine_sliding.cpp), when roughFaces_: the phase of ball i from its state
  // now (its path starting now), after anything changed it; a ball that is still rests.
  void refreshFace(int i, RunStats& stats);
  // The phase's end: a slide's slip or a roll's speed reached zero, exactly, or a turning
  // phase's direction is taken again.
  void endPhase(int i, RunStats& stats);
  void findPhaseEnd(int i);
  // `swept`: a resting ball on a face, kicked by `kick` that the face holds, spins down.
  void spinInPlace(int i, const Vec3& kick);
  // Ball i, at rest now, keeps only its spin about the face it rests on, if any.
  void restOnFace(int i);
  // The friction coefficients of static shape `ref`.
  const ContactFriction& shapeFriction(StaticRef ref) const;

  // Resting (engine_resting.cpp).
  // Stops ball i where it is, or moved by `settle` onto the supports that carry it (RestCheck)
  // when that overlaps nothing.
  void putToRest(int i, RunStats& stats, const Vec3& settle = Vec3::Zero());
  void wake(int i, RunStats& stats);
  // Wakes those of `balls` still resting, and predicts them.
  void wakeEach(const std::vector<int>& balls, RunStats& stats);
  // The resting balls that may rest on ball k: above it, their gap to it above
  // `minGapFraction` and at most kSupportGapFraction of the smaller radius.
  std::vector<int> restingAbove(int k, double minGapFraction) const;
  // A contact along unit normal n (towards ball i) slow enough to end in rest: when RestCheck
  // holds, ball i rests, and this returns true; resting balls that cannot carry it wake.
  bool restsOnContact(int i, const Vec3& n, double restitution, RunStats& stats);

  // The held ball (engine_grab.cpp).
  // The held ball h meets a static shape: it slides along what it touches, as far as its
  // steering takes it, and bounces off nothing (it has no mass to bounce with).
  void heldMeetsStatic(int h, StaticRef ref, RunStats& stats, std::vector<CollisionRecord>* log);
  // The held ball h meets ball o: o answers as against an unlimited mass moving at h's velocity.
  void pushByHeld(int h, int o, RunStats& stats, std::vector<CollisionRecord>* log);
  // Whether held ball h, pushing ball o along unit normal n (from h to o), would crush it
  // against a static shape or a resting ball (tolerance::kCrushEscapeFactor).
  bool crushes(int h, int o, const Vec3& n) const;
  void stopGrab(GrabStopKind kind, int other);

  const Bodies& bodies_;
  Vec3 gravity_;
  Vec3 pathAcceleration_;
  bool straightPaths_;
  double collapseSpeed_;
  double now_;
  double horizon_ = std::numeric_limits<double>::infinity();
  std::uint64_t pairTests_ = 0;  // added to the stats when advanceTo returns
  Vec3 zero_ = Vec3::Zero();
  std::vector<Track> tracks_;
  std::vector<Particle> particles_;
  // Each ball's angular velocity at its path's start: free flight keeps it, impacts with friction
  // change it, and so do faces with friction (faces_).
  std::vector<Vec3> spin_;
  // Friction's phases on faces: only for true paths (`exact`) in a scene with friction; `swept`
  // takes friction at its kicks instead (setVelocities).
  bool roughFaces_;
  struct FaceContact {
    FaceMotion motion;
    Vec3 normal = Vec3::Zero();                            // of the face, or zero off any
    double normalDecay = 0.0;                              // of the spin about it (spinDecayRate)
    double end = std::numeric_limits<double>::infinity();  // the phase's, absolute
  };
  std::vector<FaceContact> faces_;  // per ball, when roughFaces_
  // A turning phase's exact path (FaceMotion::turning), from `from` at `since`; the phase's
  // acceleration is then its stand-in's over one segment, which the phase's end closes. Kept
  // apart from faces_, which the loop reads for every ball.
  struct TurningFace {
    std::optional<TurningFacePath> path;
    Vec3 from = Vec3::Zero();
    double since = 0.0;
    TurningFacePath::State at(double t) const { return path->at(t - since); }
  };
  std::vector<TurningFace> turningFaces_;  // per ball, when roughFaces_
  struct Prediction {
    Contact contact;
    CellLevels::Crossing crossing;
  };
  std::vector<Prediction> predictions_;
  struct TouchedStatic {
    Vec3 normal;
    double restitution;
    StaticKind kind;
  };
  std::vector<TouchedStatic> touchedStatics_;  // leaveTouchingStatics's, kept to save allocations
  std::vector<double> restSpeed_;
  // Normal speed below which a contact with a pressing plane is a slide: a bounce no higher than
  // touching distance, or one step's kick of gravity under `swept`.
  std::vector<double> slideSpeed_;
  SlideSurfaces slides_;
  EnergyBooks books_;
  std::vector<Vec3> creaseLine_;          // per ball in a crease: the unit direction of its line
  std::vector<Vec3> creaseAcceleration_;  // and the path acceleration along it
  CellLevels cells_;
  EventQueue queue_;
  HeldBall held_;
};

}  // namespace carom
