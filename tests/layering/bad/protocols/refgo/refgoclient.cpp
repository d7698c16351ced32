#include "devices/movingcap/movingcapdrive.h"
#include "vabus/vabusclient.h"
