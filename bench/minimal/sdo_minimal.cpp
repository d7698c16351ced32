// The smallest SDO client we can write: plain C++ and POSIX sockets, no Qt. Over SLCAN tunnelled
// in TCP it sends one expedited upload request (CiA 301 7.2.4.3.6, ccs 2) for an object, waits
// for the node's answer frame, and repeats; prints round trips per second. It sets the ceiling of
// link + device that our engine is compared with.
//   sdo_minimal --uri canopen+slcan://HOST:PORT?node=N [--count N] [--object 6041:0]
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <strings.h>
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
    std::string uri, object = "6041:0";
    long count = 20000;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        if (key == "--uri")
            uri = argv[i + 1];
        else if (key == "--count")
            count = std::max(1L, std::atol(argv[i + 1]));
        else if (key == "--object")
            object = argv[i + 1];
    }
    const auto portStart = uri.rfind(':'), nodeStart = uri.find("node=");
    if (uri.rfind("canopen+slcan://", 0) != 0 || portStart < 16 || nodeStart == std::string::npos) {
        std::fprintf(stderr,
                     "sdo_minimal: --uri canopen+slcan://HOST:PORT?node=N needed, not '%s'\n",
                     uri.c_str());
        return 2;
    }
    const std::string host = uri.substr(16, portStart - 16);
    const std::string port =
        uri.substr(portStart + 1, uri.find_first_of("/?", portStart) - portStart - 1);
    const unsigned node = unsigned(std::atoi(uri.c_str() + nodeStart + 5));
    unsigned index = 0, sub = 0;
    if (node < 1 || node > 127 || std::sscanf(object.c_str(), "%x:%x", &index, &sub) != 2) {
        std::fprintf(stderr, "sdo_minimal: bad node or --object INDEX:SUB (hex)\n");
        return 2;
    }
    addrinfo hints {}, *address = nullptr;
    hints.ai_socktype = SOCK_STREAM;
    if (getaddrinfo(host.c_str(), port.c_str(), &hints, &address) != 0) {
        std::fprintf(stderr, "sdo_minimal: cannot resolve %s\n", uri.c_str());
        return 1;
    }
    const int fd = socket(address->ai_family, SOCK_STREAM, 0);
    const int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    if (connect(fd, address->ai_addr, address->ai_addrlen) != 0) {
        std::fprintf(stderr, "sdo_minimal: connect %s: %s\n", uri.c_str(), std::strerror(errno));
        return 1;
    }
    freeaddrinfo(address);
    // Open the channel as a Lawicel adapter wants (close, 125 kbit/s, open); acks are ignored.
    const char setup[] = "C\rS4\rO\r";
    char request[32], answer[8];
    std::snprintf(request, sizeof request, "t%03X840%02X%02X%02X00000000\r", 0x600 + node,
                  index & 0xFF, index >> 8, sub);
    std::snprintf(answer, sizeof answer, "t%03X8", 0x580 + node);
    if (write(fd, setup, sizeof setup - 1) != ssize_t(sizeof setup - 1))
        return std::perror("sdo_minimal: write"), 1;
    char buffer[4096];
    std::string line;
    const std::clock_t cpuStart = std::clock();
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < count; ++i) {
        if (write(fd, request, std::strlen(request)) != ssize_t(std::strlen(request)))
            return std::perror("sdo_minimal: write"), 1;
        // Lines end in CR; acks ("\r", "z\r") and other nodes' frames are skipped.
        for (bool answered = false; !answered;) {
            const ssize_t n = read(fd, buffer, sizeof buffer);
            if (n <= 0)
                return std::fprintf(stderr, "sdo_minimal: connection closed\n"), 1;
            for (ssize_t k = 0; k < n; ++k) {
                if (buffer[k] != '\r') {
                    line += buffer[k];
                    continue;
                }
                if (strncasecmp(line.c_str(), answer, 5) == 0) {
                    if (line.compare(5, 2, "80") == 0) // abort: the object cannot be read
                        return std::fprintf(stderr, "sdo_minimal: abort %s\n", line.c_str()), 1;
                    answered = true;
                }
                line.clear();
            }
        }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpuUs = double(std::clock() - cpuStart) * 1e6 / CLOCKS_PER_SEC / double(count);
    std::printf("sdo minimal: %ld round trips in %.3f s = %.0f/s, cpu %.1f us per round trip\n",
                count, seconds, double(count) / seconds, cpuUs);
    close(fd);
    return 0;
}
