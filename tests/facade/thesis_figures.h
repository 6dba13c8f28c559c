// The description texts of Finkenzeller's figures (digest-001 §2.5, §2.6), verbatim, for the
// facade tests that read them.
#pragma once

namespace veduta::thesis {

// Fig. 5.7 (L1043): a brick bond with a tall ("armiert") brick.
inline constexpr const char *kFigure5_7 = R"(Brick1 { 2.0, 0.5, 0.1; 206,78,51; 255,147,124; }
Brick2 { 2.0, 1.0, 0.1; 206,78,51; 255,147,124; }
Pattern { -1.0, "Brick1", "Brick2"; 0.0, "Brick1", 2.0; 1.0, "Brick1"; }
BrickMasonry { "Pattern"; 0.05; 102,102,102; })";

// Fig. 5.20 (L1157): a main cornice.
inline constexpr const char *kFigure5_20 =
    R"(Modifications { line, rel, 90, 0.3; line, rel, -90, 10.0; line, rel, 90, 0.6; line, rel, -90, 11.0;
line, rel, 90, 0.6; line, rel, -90, 0.6; line, rel, 90, 0.6; line, rel, -90, 2.0; line, rel, 90, 2.0;
arc, rel, 0, -90, 4.0; line, rel, 90, 5.0; line, rel, -90, 5.0; line, rel, 90, 0.6; line, rel, -90, 0.6;
line, rel, 45, 7.0; line, rel, -45, 0.6; line, rel, 90, 0.6; line, rel, -90, 2.0; line, rel, -84, 22.0; })";

// Its lines-only prefix (digest §8 row 10): a cross section that stays out of the wall.
inline constexpr const char *kFigure5_20Lines =
    R"(Modifications { line, rel, 90, 0.3; line, rel, -90, 10.0; line, rel, 90, 0.6; line, rel, -90, 11.0;
line, rel, 90, 0.6; line, rel, -90, 0.6; line, rel, 90, 0.6; line, rel, -90, 2.0; line, rel, 90, 2.0; })";

// Fig. 5.28 (L1216): a frieze with one console, abstand 1.5, 0.35 × 0.45 profile units.
inline constexpr const char *kFigure5_28 =
    R"(Modifications { line, rel, 0, 0.2; arc, abs, 90, 45, 0.5, 0, 1, 2; line, rel, -90, 0.4; }
Consoles { 1.5; "objects/simple_console.obj", 0.35, 0.45; }
TextureDescs { "textures/frieze.bmp", 0.0, 0.625, 0.04875, 0.25;
               "textures/frieze.bmp", 0.0, 1.0, 0.5, 0.625;
               "textures/frieze.bmp", 0.953125, 0.625, 1.0, 0.25; })";

}  // namespace veduta::thesis
