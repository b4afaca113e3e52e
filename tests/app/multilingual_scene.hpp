#pragma once
// A small scene whose words are Polish, Greek and mathematics: the glyph check and the subtitle
// tests read the same text.

namespace collide::test {

inline constexpr const char* multilingual_scene = R"(title = "Zderzenia: Δt ≈ 0.01 s"
description = "Gaz w pudełku; σ → η"
disc = [
  { position = [0.3, 0.5], velocity = [0.5, 0], radius = 0.05, mass = 1 },
  { position = [0.7, 0.5], velocity = [-0.5, 0], radius = 0.05, mass = 1 },
]

[box]
width = 1.0
height = 1.0
boundary = "walls"

[render]
duration = 4.0
caption = "Kule się zderzają"

[[render.captions]]
at = 2.5
text = "Energia ± 0: E = ½mv²"
)";

}  // namespace collide::test
