#include "tracesource.h"

namespace db::scope {

namespace {
// Queued connections (a source on another thread) need the sample types registered.
const int kRegistered = [] {
    qRegisterMetaType<TraceSample>();
    qRegisterMetaType<TraceSamples>();
    qRegisterMetaType<ChannelInfo>();
    return 0;
}();
} // namespace

} // namespace db::scope
