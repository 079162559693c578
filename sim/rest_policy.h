#pragma once
// Resting contact and inelastic collapse. Under gravity a ball with restitution below one bounces
// ever lower and ever faster; an event-driven solver would stall on those bounces. The policy
// (docs/physics.md, "Resting contact"):
//  1. A contact that gravity presses together (floor, cylinder top, a resting ball below)
//     separates at no less than the rest speed: the speed of a bounce kRestHeightFraction of the
//     ball's radius high. The extra speed is taken from the ball's tangential motion when it has
//     enough, so sliding balls hop along at constant energy.
//  2. A ball that meets a surface slower than twice the rest speed in every direction, while the
//     static shapes, resting balls and slow balls it touches hold it against gravity, is put to
//     rest: it stops and is no longer scheduled.
//  3. A resting ball hit at twice the rest speed or faster wakes, and so does every resting ball
//     that touches it from above (it may rest on it). A gentler hit treats it as immovable.
//  4. Without gravity, collisions separate at no less than kCollapseSpeedFraction of the scene's
//     initial RMS speed, which stops inelastic collapse in a free gas.

#include "sim/scene.h"

namespace carom {

double restSpeed(const Vec3& gravity, double radius);

// The speed of a bounce no higher than touching distance (kTouchFraction of the radius): a
// contact with a plane slower than that is a slide.
double slideSpeed(const Vec3& gravity, double radius);

double collapseSpeed(double initialRmsSpeed);

}  // namespace carom
