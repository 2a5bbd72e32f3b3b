// A walkthrough's cameras: frames interpolated along a path of keyframes.
#pragma once

#include <scene/scene.h>

#include <vector>

namespace rayrad::scene {

/// `frames` cameras along the keyframes, the first and last at the first and last
/// keyframe. Keyframe i sits at time t_i, the motion so far: the sum over the segments
/// before it of |Δposition| (m) + the angle the viewing direction turns (rad, 1 rad
/// counting as 1 m) + |Δvfov| (rad), so a walkthrough moves at an even pace however its
/// keyframes are spaced; frame k is at t = T k / (frames − 1). Position and look_at follow
/// a cubic Hermite spline through the keyframes with Catmull–Rom tangents
/// m_i = (p_{i+1} − p_{i−1}) / (t_{i+1} − t_{i−1}) (one-sided at the ends); up is
/// normalised-linear and the field of view linear within a segment. Throws
/// std::invalid_argument when the keyframes do not move at all, or a frame ends up
/// looking along its up vector or at its own position.
std::vector<Camera> framesAlongPath(const std::vector<Camera>& keyframes, int frames);

}  // namespace rayrad::scene
