#include <impetus/mechanics/relativity.hpp>
