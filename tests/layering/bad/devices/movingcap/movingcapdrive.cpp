#include "scope/recorder.h"
