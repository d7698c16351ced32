#include "canopen/sdoclient.h"
