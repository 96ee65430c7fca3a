// The whole math layer (appendices A-C): vectors, matrices, quaternions, rotations, transforms.
#pragma once

#include <impetus/math/mat22.hpp>
#include <impetus/math/mat33.hpp>
#include <impetus/math/quat.hpp>
#include <impetus/math/rot2.hpp>
#include <impetus/math/scalar.hpp>
#include <impetus/math/symmetric_eigen.hpp>
#include <impetus/math/transform2.hpp>
#include <impetus/math/transform3.hpp>
#include <impetus/math/validate.hpp>
#include <impetus/math/vec2.hpp>
#include <impetus/math/vec3.hpp>
