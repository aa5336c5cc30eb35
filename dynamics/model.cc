#include "dynamics/model.h"
