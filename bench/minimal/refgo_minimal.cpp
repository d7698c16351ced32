// The smallest RefGo client we can write: plain C++ and POSIX sockets, no Qt. Sends one object
// read ("OR6041,0\r"), waits for the prompt '>' that ends the answer, and repeats; prints round
// trips per second. It sets the ceiling of link + device that our engine is compared with.
// --wait poll waits in poll() (with a time limit, as an event loop does) before each read
// instead of blocking in read(): the cost of the event loop's extra system call alone.
//   refgo_minimal --uri refgo://HOST:PORT [--count N] [--object 6041:0] [--wait read|poll]
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

int main(int argc, char **argv)
{
    std::string uri, object = "6041:0", wait = "read";
    long count = 20000;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        if (key == "--uri")
            uri = argv[i + 1];
        else if (key == "--count")
            count = std::max(1L, std::atol(argv[i + 1]));
        else if (key == "--object")
            object = argv[i + 1];
        else if (key == "--wait")
            wait = argv[i + 1];
    }
    const auto hostStart = uri.find("://"), portStart = uri.rfind(':');
    if (uri.rfind("refgo://", 0) != 0 || portStart == std::string::npos || portStart < 8) {
        std::fprintf(stderr, "refgo_minimal: --uri refgo://HOST:PORT needed, not '%s'\n",
                     uri.c_str());
        return 2;
    }
    const std::string host = uri.substr(hostStart + 3, portStart - hostStart - 3);
    const std::string port =
        uri.substr(portStart + 1, uri.find_first_of("/?", portStart) - portStart - 1);
    addrinfo hints {}, *address = nullptr;
    hints.ai_socktype = SOCK_STREAM;
    if (getaddrinfo(host.c_str(), port.c_str(), &hints, &address) != 0) {
        std::fprintf(stderr, "refgo_minimal: cannot resolve %s\n", uri.c_str());
        return 1;
    }
    const int fd = socket(address->ai_family, SOCK_STREAM, 0);
    const int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    if (connect(fd, address->ai_addr, address->ai_addrlen) != 0) {
        std::fprintf(stderr, "refgo_minimal: connect %s: %s\n", uri.c_str(), std::strerror(errno));
        return 1;
    }
    freeaddrinfo(address);
    if (wait != "read" && wait != "poll") {
        std::fprintf(stderr, "refgo_minimal: --wait read or poll, not '%s'\n", wait.c_str());
        return 2;
    }
    const bool polls = wait == "poll";
    std::string request = "OR" + object + "\r";
    request.replace(request.find(':'), 1, ",");
    char buffer[4096];
    std::string first; // the first answer, checked once: the object must exist
    const std::clock_t cpuStart = std::clock();
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < count; ++i) {
        if (write(fd, request.data(), request.size()) != ssize_t(request.size()))
            return std::perror("refgo_minimal: write"), 1;
        // The answer is the echo, the result line and the prompt '>' (nothing follows it).
        for (bool prompt = false; !prompt;) {
            pollfd readable { fd, POLLIN, 0 };
            if (polls && poll(&readable, 1, 1000) != 1)
                return std::fprintf(stderr, "refgo_minimal: no answer within 1 s\n"), 1;
            const ssize_t n = read(fd, buffer, sizeof buffer);
            if (n <= 0)
                return std::fprintf(stderr, "refgo_minimal: connection closed\n"), 1;
            prompt = std::memchr(buffer, '>', size_t(n)) != nullptr;
            if (i == 0)
                first.append(buffer, size_t(n));
        }
        if (i == 0 && first.find("ERROR") != std::string::npos)
            return std::fprintf(stderr, "refgo_minimal: %s", first.c_str()), 1;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpuUs = double(std::clock() - cpuStart) * 1e6 / CLOCKS_PER_SEC / double(count);
    std::printf("refgo minimal: %ld round trips in %.3f s = %.0f/s, cpu %.1f us per round trip\n",
                count, seconds, double(count) / seconds, cpuUs);
    close(fd);
    return 0;
}
