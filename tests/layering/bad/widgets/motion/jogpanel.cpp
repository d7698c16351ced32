#include "app/gui/mainwindow.h"
#include "canopen/device/sdoserver.h"
#include "simulation/simulatedaxis.h"
