#pragma once
// The default OpenGL surface format the VTK views need (3.2 core, RGBA8, depth 24, no stencil,
// no multisampling). Call before QApplication is constructed: main() and the GUI tests do.
namespace lipsync::studio {

void setDefaultSurfaceFormat();

} // namespace lipsync::studio
