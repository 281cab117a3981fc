#pragma once
/// Contact with Coulomb friction and Newton restitution (reference/contact.hpp has the exact
/// motions).
#include "mechcheck/contact/coulomb.hpp"
