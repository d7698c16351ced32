// Where a client's round trip goes, seen from its system calls: loaded with LD_PRELOAD into any
// of the round-trip clients (the minimal ones or our engine's benchmarks), it times the calls on
// sockets and the gaps between them and prints, when the process ends, each phase's median (per
// occurrence) and its total per round trip, in microseconds; the totals add up to the round
// trip:
//   answer->request  from the end of the read that brought an answer to the next request's write
//                    (the client's own work on the critical path)
//   write            the request's write (on loopback this includes delivering it to the device)
//   request->wait    from the end of that write until the client waits again (poll)
//   wait             the time in poll (an event loop's wait for the answer)
//   wake->read       from poll's return to the read
//   read             the read (a blocking client waits in it)
//   round trip       from one request's write to the next
// Only sockets count (read/write looked up once per descriptor; recv/send are sockets' own);
// the event loop's eventfd and files do not.
//   LD_PRELOAD=build/bench/minimal/libroundtrip_phases.so CLIENT ARGS...
#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

using ReadFn = ssize_t (*)(int, void *, size_t);
using WriteFn = ssize_t (*)(int, const void *, size_t);
using RecvFn = ssize_t (*)(int, void *, size_t, int);
using SendFn = ssize_t (*)(int, const void *, size_t, int);
using PollFn = int (*)(pollfd *, nfds_t, int);
using PpollFn = int (*)(pollfd *, nfds_t, const timespec *, const sigset_t *);

long long nowNs()
{
    timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1000000000LL + t.tv_nsec;
}

struct Phase
{
    const char *name;
    std::vector<long long> ns;
    void add(long long value)
    {
        if (ns.size() < ns.capacity())
            ns.push_back(value); // the capacity is reserved up front: no allocation while timing
    }
};

constexpr size_t kSamples = 1000000;
constexpr int kFds = 4096;

struct State
{
    Phase answerToRequest { "answer->request", {} }, write { "write", {} },
        requestToWait { "request->wait", {} }, wait { "wait", {} }, wakeToRead { "wake->read", {} },
        read { "read", {} }, roundTrip { "round trip", {} };
    long long lastRead = 0, lastWriteEnd = 0, lastWriteStart = 0, lastWake = 0;
    signed char socketFd[kFds] = {}; // 0 not looked up, 1 a socket, -1 something else
    ReadFn realRead = nullptr;
    WriteFn realWrite = nullptr;
    RecvFn realRecv = nullptr;
    SendFn realSend = nullptr;
    PollFn realPoll = nullptr;
    PpollFn realPpoll = nullptr;

    State()
    {
        for (Phase *p : phases())
            p->ns.reserve(kSamples);
        realRead = reinterpret_cast<ReadFn>(dlsym(RTLD_NEXT, "read"));
        realWrite = reinterpret_cast<WriteFn>(dlsym(RTLD_NEXT, "write"));
        realRecv = reinterpret_cast<RecvFn>(dlsym(RTLD_NEXT, "recv"));
        realSend = reinterpret_cast<SendFn>(dlsym(RTLD_NEXT, "send"));
        realPoll = reinterpret_cast<PollFn>(dlsym(RTLD_NEXT, "poll"));
        realPpoll = reinterpret_cast<PpollFn>(dlsym(RTLD_NEXT, "ppoll"));
    }
    std::vector<Phase *> phases()
    {
        return { &answerToRequest, &write, &requestToWait, &wait, &wakeToRead, &read, &roundTrip };
    }
    bool isSocket(int fd)
    {
        if (fd < 0 || fd >= kFds)
            return false;
        if (socketFd[fd] == 0) {
            struct stat s;
            socketFd[fd] = fstat(fd, &s) == 0 && S_ISSOCK(s.st_mode) ? 1 : -1;
        }
        return socketFd[fd] == 1;
    }
    // The phases around one read or write on a socket; `call` makes it.
    template<typename Call>
    ssize_t timedRead(Call call)
    {
        const long long start = nowNs();
        if (lastWake)
            wakeToRead.add(start - lastWake);
        lastWake = 0;
        const ssize_t n = call();
        const long long end = nowNs();
        if (n > 0) {
            read.add(end - start);
            lastRead = end;
        }
        return n;
    }
    template<typename Call>
    ssize_t timedWrite(Call call)
    {
        const long long start = nowNs();
        if (lastRead)
            answerToRequest.add(start - lastRead);
        if (lastWriteStart)
            roundTrip.add(start - lastWriteStart);
        lastRead = 0;
        lastWriteStart = start;
        const ssize_t n = call();
        lastWriteEnd = nowNs();
        write.add(lastWriteEnd - start);
        return n;
    }
    void beforeWait()
    {
        if (lastWriteEnd)
            requestToWait.add(nowNs() - lastWriteEnd);
        lastWriteEnd = 0;
    }
};

State &state()
{
    static State s;
    return s;
}

void report(Phase &p, size_t roundTrips)
{
    if (p.ns.empty()) {
        std::fprintf(stderr, " | %s -", p.name);
        return;
    }
    double sum = 0;
    for (long long v : p.ns)
        sum += double(v);
    std::nth_element(p.ns.begin(), p.ns.begin() + p.ns.size() / 2, p.ns.end());
    std::fprintf(stderr, " | %s %.2f/%.2f", p.name, double(p.ns[p.ns.size() / 2]) / 1000.0,
                 sum / double(std::max<size_t>(roundTrips, 1)) / 1000.0);
}

// Made before the state's first use by the program, so the state outlives it.
struct Reporter
{
    Reporter() { state(); }
    ~Reporter()
    {
        State &s = state();
        const size_t roundTrips = s.roundTrip.ns.size();
        std::fprintf(stderr, "round-trip phases (us, median/per round trip, %zu round trips)",
                     roundTrips);
        for (Phase *p : s.phases())
            report(*p, roundTrips);
        std::fprintf(stderr, "\n");
    }
} reporter;

} // namespace

extern "C" {

ssize_t read(int fd, void *buffer, size_t size)
{
    State &s = state();
    if (!s.isSocket(fd))
        return s.realRead(fd, buffer, size);
    return s.timedRead([&] { return s.realRead(fd, buffer, size); });
}

ssize_t recv(int fd, void *buffer, size_t size, int flags)
{
    State &s = state();
    return s.timedRead([&] { return s.realRecv(fd, buffer, size, flags); });
}

ssize_t write(int fd, const void *buffer, size_t size)
{
    State &s = state();
    if (!s.isSocket(fd))
        return s.realWrite(fd, buffer, size);
    return s.timedWrite([&] { return s.realWrite(fd, buffer, size); });
}

ssize_t send(int fd, const void *buffer, size_t size, int flags)
{
    State &s = state();
    return s.timedWrite([&] { return s.realSend(fd, buffer, size, flags); });
}

int poll(pollfd *fds, nfds_t count, int timeoutMs)
{
    State &s = state();
    s.beforeWait();
    const long long start = nowNs();
    const int n = s.realPoll(fds, count, timeoutMs);
    s.lastWake = nowNs();
    s.wait.add(s.lastWake - start);
    return n;
}

int ppoll(pollfd *fds, nfds_t count, const timespec *timeout, const sigset_t *mask)
{
    State &s = state();
    s.beforeWait();
    const long long start = nowNs();
    const int n = s.realPpoll(fds, count, timeout, mask);
    s.lastWake = nowNs();
    s.wait.add(s.lastWake - start);
    return n;
}

} // extern "C"
