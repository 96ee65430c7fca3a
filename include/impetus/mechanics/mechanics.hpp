// The mechanics layer (chapters 2-6): closed-form and near-closed-form models, double precision.
#pragma once

#include <impetus/mechanics/aerodynamics.hpp>
#include <impetus/mechanics/aiming.hpp>
#include <impetus/mechanics/cannon.hpp>
#include <impetus/mechanics/explosion.hpp>
#include <impetus/mechanics/forces.hpp>
#include <impetus/mechanics/friction.hpp>
#include <impetus/mechanics/impact.hpp>
#include <impetus/mechanics/kinematics.hpp>
#include <impetus/mechanics/kinetics.hpp>
#include <impetus/mechanics/projectile.hpp>
#include <impetus/mechanics/relativity.hpp>
#include <impetus/mechanics/rocket.hpp>
