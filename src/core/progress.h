// Progress of long work on a terminal: stage, percent, rate and ETA on one updating line.
// Silent when stderr is not a terminal or when asked to be quiet, so logs stay clean.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace veduta {

class Progress {
  public:
    // `unit` names what is counted ("tiles"). Shown only if `enabled` and stderr is a tty.
    Progress(std::string stage, uint64_t total, std::string unit, bool enabled);
    ~Progress();

    // Thread-safe; redraws at most a few times a second.
    void advance(uint64_t count = 1);
    void finish();

  private:
    void draw(uint64_t done, bool final);

    std::string stage_, unit_;
    uint64_t total_;
    bool enabled_;
    std::atomic<uint64_t> done_{0};
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_;
    std::mutex drawMutex_;
    bool finished_ = false;
};

std::string formatDuration(double seconds);

}  // namespace veduta
