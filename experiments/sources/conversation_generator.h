// Generated conversations: two or three people talking, with a script, for testing an
// editor on conversations nobody tuned it for and for timing it on long ones. Each seed
// draws a layout -- standing face to face (or in a triangle), walking side by side,
// one circling the other, or two talking while a third comes in (an action) and joins --
// pillars around them that never touch their paths, and lines of 1.5 to 7 s passed between
// the speakers, with short pauses. The scene has actors and a script and nobody to chase:
// it is edited (experiments/runs/edit_run.h). Built as YAML text and read by the scene
// reader, so it is valid by the same rules as any scene file.
#pragma once

#include <cstdint>
#include <string>

#include "sightline/domains/camera/scene.h"

namespace sightline::experiments {

struct ConversationOptions {
  std::uint64_t seed = 1;
  double seconds = 40;  // the conversation's length
  int layout = -1;      // 0 standing, 1 walking, 2 circling, 3 someone comes in; -1: by seed
};

// The scene file's text (YAML), and the scene.
std::string conversation_yaml(const ConversationOptions& options);
camera::Scene generate_conversation(const ConversationOptions& options);

}  // namespace sightline::experiments
