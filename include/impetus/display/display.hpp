// The display layer (chapter 24): stereo 3D, frustums and matrices per eye, parallax, anaglyph.
// Namespace impetus::display.
#pragma once

#include <impetus/display/anaglyph.hpp>
#include <impetus/display/matrix4.hpp>
#include <impetus/display/stereo.hpp>
#include <impetus/display/stereo_frustum.hpp>
