#include "qcustomplot.h"
