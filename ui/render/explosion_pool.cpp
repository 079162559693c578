#include "ui/render/explosion_pool.h"

#include <algorithm>

namespace carom::render {

ExplosionPool::ExplosionPool(int limit) : limit_(std::max(0, limit)) {}

void ExplosionPool::setLimit(int limit) {
  limit_ = std::max(0, limit);
  if (count() > limit_) explosions_.erase(explosions_.begin(), explosions_.end() - limit_);
}

bool ExplosionPool::add(const Vec3& point, double size, double now) {
  update(now);
  if (count() >= limit_) {
    ++dropped_;
    return false;
  }
  explosions_.push_back({point, size, now_});
  return true;
}

void ExplosionPool::update(double now) {
  now_ = std::max(now_, now);  // a clock that went back would bring faded ones back to life
  removeFinished();
}

void ExplosionPool::removeFinished() {
  std::erase_if(explosions_, [this](const Explosion& e) { return now_ - e.born >= kLifetime; });
}

std::vector<ExplosionPool::Live> ExplosionPool::live() const {
  std::vector<Live> result;
  result.reserve(explosions_.size());
  for (const Explosion& e : explosions_) {
    const double age = std::clamp((now_ - e.born) / kLifetime, 0.0, 1.0);
    result.push_back({e.centre, e.size * (1.0 + kGrowth * age), 1.0 - age});
  }
  return result;
}

}  // namespace carom::render
