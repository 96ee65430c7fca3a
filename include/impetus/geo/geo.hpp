// The geo layer (ch. 22): GPS and geodesy in double precision, no third-party dependency.
// GeographicLib's reference geodesic is in the optional impetus::geo target (geo/geodesic.hpp).
#pragma once

#include <impetus/geo/coordinates.hpp>
#include <impetus/geo/ellipsoid.hpp>
#include <impetus/geo/gps_clock.hpp>
#include <impetus/geo/great_circle.hpp>
#include <impetus/geo/rhumb.hpp>
#include <impetus/geo/trilateration.hpp>
#include <impetus/geo/vincenty.hpp>
