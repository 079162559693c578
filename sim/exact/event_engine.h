#pragma once
// The earliest-contact-first loop shared by the `exact` and `swept` methods: every ball carries
// one predicted event (a contact or a move to the next grid cell) in the event queue; the
// earliest is processed, only the balls it changed are predicted again, and predictions that
// involved a ball changed since are dropped when their time comes (collision counters).
//
// Its cells and their static shapes are in engine_cells.cpp, its sliding and its rest decisions
// in engine_sliding.cpp and engine_resting.cpp.
//
// Balls of very different sizes live in grids of their own (levels, by size class): cells sized
// by the largest ball of all would put thousands of small balls in one cell. A ball finds the
// larger balls it may touch in the cells of their levels around it, and the smaller ones in
// their levels' cells under its own level's block of 3x3x3 cells (Ogarko and Luding, "A fast
// multilevel algorithm for contact detection of arbitrarily polydisperse objects", 2012). It
// follows its position in every larger level's grid by crossing events, as in its own.
//
// A ball at least eight times larger than another level's balls follows its cell in that
// level's grid too, and finds them in the box of cells its own size around it rather than under
// its block, which is 27 times the volume: every collision of a boulder ploughing through sand
// predicts it again against every grain so found. A grain then looks for boulders in their
// level's block around it at each of its own crossings.
//
// Balls move lazily: each keeps its path from the time it last changed, so an event costs
// O(neighbours + log N), not O(N).

#include "sim/dynamics/bodies.h"
#include "sim/dynamics/grab.h"
#include "sim/dynamics/run_stats.h"
#include "sim/exact/cell_grid.h"
#include "sim/exact/event_queue.h"
#include "sim/geometry/contact_time.h"
#include "sim/geometry/motion.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace carom {

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
  std::string gridSummary() const;
  BallState stateOf(int ball) const;
  std::vector<BallState> state() const;

  // Events after `time` need not be predicted (the end of a swept step): they are left out,
  // which saves work; they are found when the engine is told about the next step.
  void setHorizon(double time) { horizon_ = time; }

  // Replaces every ball's velocity at now() (for the integrator kicks of `swept`) and predicts
  // all events again. The held ball keeps its own.
  void setVelocities(const std::vector<Vec3>& velocities);

  // The held ball (grab.h, Stepper::hold).
  void hold(int i, const Vec3& velocity, RunStats& stats);
  void release(const Vec3& velocity);
  void place(const Vec3& position);
  int held() const { return held_; }
  std::optional<GrabStop> takeGrabStop() {
    std::optional<GrabStop> stop;
    stop.swap(grabStop_);
    return stop;
  }

  // The memory the engine holds, in bytes.
  std::size_t memoryBytes() const;

 private:
  // SlideEnd: a ball sliding on a box's face or a capped cylinder's cap reaches its edge or rim.
  enum class EventKind : std::uint8_t { None, Ball, Plane, Cylinder, Box, SlideEnd };
  // What a neighbour search reads of every ball, in one cache line.
  struct alignas(64) Track {
    Motion motion;
    double radius;
  };
  struct Particle {
    CellGrid::Coords coords{};  // in its level's grid
    int cell = 0;               // its cell, numbered across all levels
    std::int8_t level = 0;
    int staticBegin = 0;  // the cell's static shapes in statics_, kept here to save a lookup
    int staticEnd = 0;
    std::uint32_t counter = 0;  // changes whenever the path changes
    int collisionsInBurst = 0;
    double lastSurfaceCollision = -std::numeric_limits<double>::infinity();
    int slidePlane = -1;   // the surface (slideSurfaces_) the ball slides on, or -1 in flight
    int creasePlane = -1;  // a second one, when it slides along the crease of the two
    bool resting = false;
    // Put to rest by the burst guard: held in its wedge, it is not loosened (restCheck).
    bool wedged = false;
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
  struct Crossing {
    double time = std::numeric_limits<double>::infinity();  // absolute
    std::int8_t axis = 0;
    std::int8_t direction = 0;
    std::int8_t level = 0;  // the ball's own, or a larger one it is followed in
  };
  // The balls of one size class and their grid.
  struct CellLevel {
    CellGrid grid;
    int firstCell = 0;  // its cells' first number across all levels
    double maxRadius = 0.0;
    double minRadius = std::numeric_limits<double>::infinity();
    int balls = 0;
    // Balls in the grid's border cells, now and just after it was built: when many more have
    // wandered out there, the grid is built again around where the balls are.
    int borderBalls = 0;
    int builtBorderBalls = 0;
  };
  enum class StaticKind : std::uint8_t { Plane, Cylinder, Box };
  struct StaticRef {
    StaticKind kind;
    int index;
  };
  // What a ball may slide on: the planes (same indices), then the six faces of each box, by
  // box, axis and side, then the two caps of each cylinder, by cylinder and side (an infinite
  // one's are never used).
  struct SlideSurface {
    PlaneShape plane;  // a cap's normal tells which cap it is
    StaticRef owner;   // the plane itself, or the box or cylinder the face or cap belongs to
    int axis = -1;     // a box face's: the box's axis across it
  };

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
  static ContactKind contactKindOf(StaticKind kind) {
    return kind == StaticKind::Box        ? ContactKind::BallBox
           : kind == StaticKind::Cylinder ? ContactKind::BallCylinder
                                          : ContactKind::BallPlane;
  }
  StaticContact staticContact(int i, StaticRef ref, const Vec3& position) const;
  StaticContact staticContact(int i, StaticRef ref) const {
    return staticContact(i, ref, tracks_[i].motion.position);
  }

  // The levels and their grids around the balls' positions now.
  void buildGrid();
  void buildStaticLists();
  void noteStatics(int i);
  // Files ball i (at its position now) in its level's cell and follows it in the larger levels.
  void fileBall(int i);
  void moveToCell(int i, const CellGrid::Coords& coords);
  // Ball i's coordinates in the other levels' grids, at `at` (levelCoords).
  void noteLevelCoords(int i, const Vec3& at);
  // Builds the grids again when a level's border cells hold many more balls than when it was
  // built (balls spread beyond the region it covers): they would all be one another's
  // neighbours there.
  void rebuildCellsIfCrowded();
  // Ball i's cell coordinates in another level `level`: each larger one, and the smaller ones it
  // follows (boxReach), there in the grid's lattice continued beyond it, since a large ball
  // outside a grid of small ones would otherwise have its box reach from the border cell deep
  // into it.
  CellGrid::Coords& levelCoords(int i, int level) {
    return levelCoords_[std::size_t(i) * levels_.size() + level];
  }
  const CellGrid::Coords& levelCoords(int i, int level) const {
    return levelCoords_[std::size_t(i) * levels_.size() + level];
  }
  // Calls f(cell) for the cells of the level `finer` (numbered across levels) that meet the box
  // of level `level`'s cells from `from` to `to` (clamped to its grid), with a cell more on
  // every side against rounding.
  template <typename F>
  void forEachFinerCell(int finer, int level, CellGrid::Coords from, CellGrid::Coords to,
                        F&& f) const;
  // How far, in cells of finer level `finer`, a ball of level `level` finds that level's balls
  // around its cell there; zero when it finds them under its block instead (too close in size).
  const CellGrid::Coords& boxReach(int level, int finer) const {
    return boxReach_[std::size_t(level) * levels_.size() + finer];
  }
  bool followsFiner(int level, int finer) const { return boxReach(level, finer)[0] > 0; }
  // How far beyond the finer grid the lattice a ball of `level` follows there goes along an
  // axis: past its box's reach, the box holds no cell of the grid but its border.
  int latticeMargin(int level, int finer, int axis) const {
    return boxReach(level, finer)[axis] + 1;
  }
  // The box of cells in finer level `finer` that ball k, which follows it, finds its balls in:
  // `boxReach` around `around` (its lattice cell there, or a face of it) clamped into the grid,
  // so that a box beyond the grid still holds the border cells, which reach to infinity.
  std::pair<CellGrid::Coords, CellGrid::Coords> followerBox(int k, int finer,
                                                            const CellGrid::Coords& around) const {
    const CellGrid::Coords& reach = boxReach(particles_[k].level, finer);
    const CellGrid::Coords& counts = levels_[finer].grid.counts();
    CellGrid::Coords from, to;
    for (int a = 0; a < 3; ++a) {
      from[a] = std::clamp(around[a] - reach[a], 0, counts[a] - 1);
      to[a] = std::clamp(around[a] + reach[a], 0, counts[a] - 1);
    }
    return {from, to};
  }
  // Whether ball i's cell is in the box of larger ball k, which follows i's level.
  bool inFollowersBox(int i, int k) const {
    const Particle& p = particles_[i];
    const auto [from, to] = followerBox(k, p.level, levelCoords(k, p.level));
    for (int a = 0; a < 3; ++a)
      if (p.coords[a] < from[a] || p.coords[a] > to[a]) return false;
    return true;
  }
  // Calls f(cell) for the cells of level `level` from `from` to `to`, clamped to its grid.
  template <typename F>
  void forEachCellIn(int level, CellGrid::Coords from, CellGrid::Coords to, F&& f) const;
  // Calls f(ball) for every ball, other than i, whose cell in any level is near enough to touch i.
  template <typename F>
  void forEachNeighbourAcrossLevels(int i, F&& f) const;
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
  void findCrossing(int i, const BallPath& path);
  void schedule(int i);
  void cross(int i, RunStats& stats);
  // After ball i came to rest: a resting ball has no event of its own, so balls about to hit
  // it must be told.
  void warnNeighbours(int i);
  void process(int i, RunStats& stats, std::vector<CollisionRecord>* log);
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
  // The held ball h meets a static shape: it slides along what it touches, as far as its
  // steering takes it, and bounces off nothing (it has no mass to bounce with).
  void heldMeetsStatic(int h, StaticRef ref, RunStats& stats, std::vector<CollisionRecord>* log);
  // The held ball h meets ball o: o answers as against an unlimited mass moving at h's velocity.
  void pushByHeld(int h, int o, RunStats& stats, std::vector<CollisionRecord>* log);
  // Whether held ball h, pushing ball o along unit normal n (from h to o), would crush it
  // against a static shape or a resting ball (tolerance::kCrushEscapeFactor).
  bool crushes(int h, int o, const Vec3& n) const;
  void stopGrab(GrabStopKind kind, int other);
  // Ball i meets something that does not move (plane, cylinder, resting ball) along unit normal
  // n pointing to the ball.
  // `plane` is the plane's index when the surface is one: a slow enough contact with a plane
  // that gravity presses the ball against turns into sliding along it.
  void collideWithSurface(int i, const Vec3& n, double restitution, RunStats& stats,
                          int plane = -1);
  // The same contact when it does not end in rest.
  void bounceOffSurface(int i, const Vec3& n, double restitution, RunStats& stats, int plane = -1);
  // Sliding (docs/physics.md, "Sliding"): the ball keeps touching the plane and follows
  // gravity's component along it, an exact path, until a contact sends it off faster than a
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
  // Whether static shape `ref` is, or holds, slide surface `surface`.
  bool holdsSurface(StaticRef ref, int surface) const {
    const StaticRef owner = slideSurfaces_[surface].owner;
    return ref.kind == owner.kind && ref.index == owner.index;
  }
  // Whether ball p slides along `ref` (and so never into it).
  bool slidesAgainst(const Particle& p, StaticRef ref) const {
    return (p.slidePlane >= 0 && holdsSurface(ref, p.slidePlane)) ||
           (p.creasePlane >= 0 && holdsSurface(ref, p.creasePlane));
  }
  // The slide surface that ball i meets at a contact with `ref` now: the plane, the box face
  // (away from its edges and corners) or the cap (its centre within the disc); -1 for any other
  // part.
  int surfaceAt(int i, StaticRef ref) const;
  int boxFaceAt(int i, int box) const;
  int capAt(int i, int cylinder) const;
  // The contact's restitution of ball i with a static shape.
  double restitutionWith(int i, StaticRef ref) const;
  // When ball i, sliding on a box's face or a cap, reaches the face's edge or the cap's rim.
  void findSlideEnd(int i, const BallPath& path);
  double faceEndTime(const SlideSurface& face, const BallPath& path, double horizon) const;
  double capEndTime(const SlideSurface& cap, const BallPath& path, double horizon) const;
  // The slide's end: past the edge or rim the ball flies, or meets the shape at once when it
  // would fly into the rounding there (bendsIntoEdge, bendsIntoRim).
  void endSlide(int i, RunStats& stats, std::vector<CollisionRecord>* log);
  // Whether ball i, at the end of a slide on a box's face or a cap, would fly into the rounding
  // of the face's edge or the cap's rim at once.
  bool bendsIntoEdge(int i, const SlideSurface& face) const;
  bool bendsIntoRim(int i, const SlideSurface& cap) const;
  // After ball i's velocity changed: a sliding ball pushed into its plane bounces off it, and
  // one that now leaves it flies.
  void updateSlide(int i, RunStats& stats);
  // Puts a sliding ball back on its plane exactly, undoing round-off drift off it.
  void keepOnPlane(int i);
  void leaveTouchingStatics(int i, RunStats& stats);
  void changed(int i);
  // `swept` (straight sweeps kicked by an integrator under gravity): between two events of a
  // ball, physics keeps its energy, but the integrator's kicks and the straight sweep's chord
  // below the true parabola do not, and the errors of successive flights add up (the magic room
  // gained 96 % in 2,000 s). A contact first gives the ball back the energy it had after its
  // last event, by changing its speed along gravity, so the error never outlives one flight.
  void recordEnergy(int i);
  void restoreEnergy(int i);
  // The books after ball i's event. An elastic event keeps what physics keeps: the ball's
  // energy, changed only by `exchanged` (its share of a ball pair's exchange). What the rest
  // policy's guards gave or took in it (a slide's capture, a rest, a minimum separation) stays
  // owed, and the ball's next contact settles it, so guards make and lose nothing over time. An
  // event with an inelastic contact records the ball as it is: the guards model its collapse.
  void closeBooks(int i, double exchanged);
  void noteRestitution(double restitution) {
    inelasticEvent_ = inelasticEvent_ || restitution < 1.0;
  }
  // Stops ball i where it is, or moved by `settle` onto the supports that carry it (restCheck)
  // when that overlaps nothing.
  void putToRest(int i, RunStats& stats, const Vec3& settle = Vec3::Zero());
  bool clearAt(int i, const Vec3& centre) const;
  void wake(int i, RunStats& stats);
  // Wakes those of `balls` still resting, and predicts them.
  void wakeEach(const std::vector<int>& balls, RunStats& stats);
  // The resting balls that may rest on ball k: above it, their gap to it above
  // `minGapFraction` and at most kSupportGapFraction of the smaller radius.
  std::vector<int> restingAbove(int k, double minGapFraction) const;
  // A contact along unit normal n (towards ball i) slow enough to end in rest: when restCheck
  // holds, ball i rests, and this returns true; resting balls that cannot carry it wake.
  bool restsOnContact(int i, const Vec3& n, double restitution, RunStats& stats);
  // Not resting, and slower than a ball that may settle.
  bool slow(int k) const;
  struct Support {
    int staticSlot;  // in statics_, or -1
    int ball;        // or -1
  };
  struct SupportGap {
    Vec3 normal;
    double gap;
  };
  SupportGap supportGap(int i, const Support& support, const Vec3& centre) const;
  // What ball i touches within kSupportGapFraction of its radius: its possible supports
  // (statics, resting balls, balls slower than its rest speed) with their normals, and the
  // faster balls, which it must not settle into.
  struct NearContacts {
    std::vector<Support> supports;
    std::vector<Vec3> normals;
    std::vector<Support> moving;
  };
  NearContacts nearContacts(int i, const Vec3& centre) const;
  // Rule 3 of rest_policy.h: whether ball i can rest (its contacts hold it with the balls it
  // touches fixed, and so do its cluster's with the slow ones free, and it can settle) and
  // where: `settle` is the move, at most kSupportGapFraction of the radius, after which what it
  // touches to round-off holds it.
  struct RestCheck {
    bool holds = false;
    Vec3 settle = Vec3::Zero();
    std::vector<int> loosened;  // resting balls that cannot carry it: they must move
  };
  RestCheck restCheck(int i) const;
  std::optional<Vec3> closingMove(int i, const Vec3& centre,
                                  const std::vector<Support>& carrying) const;
  Vec3 closingStep(int i, const Vec3& at, const std::vector<Support>& supports,
                   double* residual) const;
  std::optional<Vec3> settlingMove(int i, const Vec3& centre, const NearContacts& near, Vec3 move,
                                   std::vector<Support> carrying) const;
  // Ball i at `centre` overlaps nothing, and what it touches to round-off holds it.
  bool heldAt(int i, const Vec3& centre, const NearContacts& near) const;
  std::optional<Vec3> lowestPocket(int i, const Vec3& centre, const NearContacts& near) const;
  bool clusterHolds(int i, int freed = -1) const;
  BallPath pathAt(int i, double t) const;
  const Vec3& accelerationOf(int i) const {
    // Without path acceleration nobody's flag need be read (a cache miss in the hot loop).
    if (straightPaths_) return zero_;
    const Particle& p = particles_[i];
    if (p.resting || p.held) return zero_;
    if (p.slidePlane < 0) return pathAcceleration_;
    return p.creasePlane < 0 ? slideAcceleration_[p.slidePlane] : creaseAcceleration_[i];
  }
  // What gravity does to ball i's velocity, whichever path it follows: the rest policy's view
  // (a pair that gravity presses together), the same under `exact` and `swept`.
  Vec3 gravityOn(int i) const {
    const Particle& p = particles_[i];
    if (p.resting || p.held) return Vec3::Zero();
    if (p.slidePlane < 0) return gravity_;
    if (p.creasePlane < 0) return slideGravity_[p.slidePlane];
    return gravity_.dot(creaseLine_[i]) * creaseLine_[i];
  }
  void moveTo(int i, double t) {
    tracks_[i].motion.moveTo(t, accelerationOf(i));
    if (particles_[i].slidePlane >= 0) keepOnPlane(i);
  }
  void notePenetration(double overlap, RunStats& stats) const;
  template <typename F>
  void forEachNeighbour(int i, F&& f) const {
    if (levels_.size() > 1) {
      forEachNeighbourAcrossLevels(i, f);
      return;
    }
    levels_[0].grid.forEachNeighbourCell(particles_[i].coords, [&](int cell) {
      members_.forEachIn(cell, [&](int k) {
        if (k != i) f(k);
      });
    });
  }

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
  struct Prediction {
    Contact contact;
    Crossing crossing;
  };
  std::vector<Prediction> predictions_;
  struct TouchedStatic {
    Vec3 normal;
    double restitution;
    StaticKind kind;
  };
  std::vector<TouchedStatic> touchedStatics_;  // leaveTouchingStatics's, kept to save allocations
  bool restoresEnergy_ = false;
  bool inelasticEvent_ = false;  // the event being processed has an inelastic contact
  std::vector<double> energy_;   // per unit mass, after each ball's last event (`swept`)
  // What a ball's restore could not take (it was higher than its energy allows), still owed.
  std::vector<double> energyExcess_;
  std::vector<double> restSpeed_;
  // Normal speed below which a contact with a pressing plane is a slide: a bounce no higher than
  // touching distance, or one step's kick of gravity under `swept`.
  std::vector<double> slideSpeed_;
  std::vector<SlideSurface> slideSurfaces_;
  int firstCap_ = 0;                      // the first cap's index in slideSurfaces_
  std::vector<Vec3> slideAcceleration_;   // path acceleration along each surface
  std::vector<Vec3> slideGravity_;        // gravity along each surface
  std::vector<Vec3> creaseLine_;          // per ball in a crease: the unit direction of its line
  std::vector<Vec3> creaseAcceleration_;  // and the path acceleration along it
  std::vector<CellLevel> levels_;
  std::vector<CellGrid::Coords> levelCoords_;  // per ball and level (only larger levels used)
  std::vector<CellGrid::Coords> boxReach_;     // per level and finer level (boxReach)
  bool cellsCrowded_ = false;  // a level's border cells are crowded (rebuildCellsIfCrowded)
  CellMembership members_;
  std::vector<int> staticStart_;  // CSR: static shapes near each cell
  bool sharedStatics_ = false;    // every cell uses all of statics_
  std::vector<StaticRef> statics_;
  EventQueue queue_;
  int held_ = -1;  // the held ball, or -1
  std::optional<GrabStop> grabStop_;
  // The held ball's burst guard (kMaxCollisionsInBurst): pushes in a row, each after a
  // negligible travel.
  int heldPushesInBurst_ = 0;
  double heldLastPush_ = -std::numeric_limits<double>::infinity();
};

template <typename F>
void EventEngine::forEachCellIn(int level, CellGrid::Coords from, CellGrid::Coords to,
                                F&& f) const {
  const CellLevel& cells = levels_[level];
  for (int a = 0; a < 3; ++a) {
    from[a] = std::max(from[a], 0);
    to[a] = std::min(to[a], cells.grid.counts()[a] - 1);
    if (from[a] > to[a]) return;
  }
  for (int z = from[2]; z <= to[2]; ++z)
    for (int y = from[1]; y <= to[1]; ++y)
      for (int x = from[0]; x <= to[0]; ++x) f(cells.firstCell + cells.grid.index({x, y, z}));
}

template <typename F>
void EventEngine::forEachFinerCell(int finer, int level, CellGrid::Coords from, CellGrid::Coords to,
                                   F&& f) const {
  const CellGrid& coarse = levels_[level].grid;
  const CellLevel& fine = levels_[finer];
  CellGrid::Coords low, high;
  for (int a = 0; a < 3; ++a) {
    from[a] = std::max(from[a], 0);
    to[a] = std::min(to[a], coarse.counts()[a] - 1);
    if (from[a] > to[a]) return;
    low[a] = std::max(fine.grid.coordOf(a, coarse.lowerFace(a, from[a])) - 1, 0);
    high[a] =
        std::min(fine.grid.coordOf(a, coarse.upperFace(a, to[a])) + 1, fine.grid.counts()[a] - 1);
  }
  for (int z = low[2]; z <= high[2]; ++z)
    for (int y = low[1]; y <= high[1]; ++y)
      for (int x = low[0]; x <= high[0]; ++x) f(fine.firstCell + fine.grid.index({x, y, z}));
}

template <typename F>
void EventEngine::forEachNeighbourAcrossLevels(int i, F&& f) const {
  const Particle& p = particles_[i];
  const auto visitCell = [&](int cell) {
    members_.forEachIn(cell, [&](int k) {
      if (k != i) f(k);
    });
  };
  for (int l = 0; l < static_cast<int>(levels_.size()); ++l) {
    const CellLevel& level = levels_[l];
    if (l < p.level && followsFiner(p.level, l)) {
      const auto [from, to] = followerBox(i, l, levelCoords(i, l));
      forEachCellIn(l, from, to, visitCell);
      continue;
    }
    if (l < p.level) {
      CellGrid::Coords from = p.coords, to = p.coords;
      for (int a = 0; a < 3; ++a) {
        --from[a];
        ++to[a];
      }
      forEachFinerCell(l, p.level, from, to, visitCell);
      continue;
    }
    const CellGrid::Coords& around = l == p.level ? p.coords : levelCoords(i, l);
    if (l > p.level && followsFiner(l, p.level)) {
      // Those whose boxes hold it: it meets no other.
      level.grid.forEachNeighbourCell(around, [&](int cell) {
        members_.forEachIn(level.firstCell + cell, [&](int k) {
          if (inFollowersBox(i, k)) f(k);
        });
      });
      continue;
    }
    level.grid.forEachNeighbourCell(around, [&](int cell) { visitCell(level.firstCell + cell); });
  }
}

}  // namespace carom
