#include "mesh/shape.h"
