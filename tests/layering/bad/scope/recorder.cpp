#include "morse/decode/decoder.h"
#include "widgets/scope/scopeplot.h"
#include <QWidget>
