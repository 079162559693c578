#pragma once
// Resting contact and inelastic collapse. Under gravity a ball with restitution below one bounces
// ever lower and ever faster; an event-driven solver would stall on those bounces. The policy
// (docs/physics.md, "Resting contact", where the rules are numbered as here):
//  1. A contact that gravity presses together (cylinder top, a resting ball below, a falling
//     ball on a sliding one) separates at no less than the rest speed, the speed of a bounce
//     kRestHeightFraction of the ball's radius high, when inelastic; an elastic one, which
//     cannot collapse, at no less than the slide speed (it parts when met at no speed).
//  2. A contact with a plane that gravity presses the ball against, bouncing no faster than the
//     slide speed, becomes sliding along the plane (EventEngine).
//  3. A ball that meets a surface slower than twice the rest speed in every direction, while
//     pushes at the contacts it can close hold it against gravity (contact_forces.h), alone and
//     together with the slow balls of its cluster, is put to rest: it stops and is no longer
//     scheduled.
//  4. A resting ball hit at twice the rest speed or faster wakes, and so does every resting ball
//     that touches it from above (it may rest on it). A gentler hit treats it as immovable.
//  5. Without gravity, collisions separate at no less than kCollapseSpeedFraction of the scene's
//     initial RMS speed, which stops inelastic collapse in a free gas.
//  8. Under gravity, restitution takes nothing from two balls that meet slower than the rest
//     speed, and parts faster ones at no less than it (never faster than they met): real
//     restitution tends to one at low speed, and a pile flowing down a slope cannot collapse.

#include "sim/model/scene.h"

namespace carom {

double restSpeed(const Vec3& gravity, double radius);

// The speed of a bounce no higher than touching distance (kTouchFraction of the radius): a
// contact with a plane slower than that is a slide.
double slideSpeed(const Vec3& gravity, double radius);

double collapseSpeed(double initialRmsSpeed);

}  // namespace carom
