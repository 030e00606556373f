#pragma once
/// @file The phases of the one schedule every world-building command runs (docs/DESIGN.md
/// "A frame through the schedule"): Plan once, then Stream .. Write per frame.

namespace silva {

/// Schedule phases in run order.
enum class Phase : int { Plan = 0, Stream, Generate, Place, Resolve, Prepare, Render, Write };

}  // namespace silva
