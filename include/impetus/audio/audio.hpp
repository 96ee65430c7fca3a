// The audio layer (ch. 26): waves, propagation, reflection, Doppler, binaural cues and pitch
// measurement, no third-party dependency. 3D sound through OpenAL Soft is in the optional
// impetus::audio target (audio/openal_renderer.hpp, audio/wav_file.hpp).
#pragma once

#include <impetus/audio/binaural.hpp>
#include <impetus/audio/doppler.hpp>
#include <impetus/audio/pitch.hpp>
#include <impetus/audio/propagation.hpp>
#include <impetus/audio/reflection.hpp>
#include <impetus/audio/waves.hpp>
