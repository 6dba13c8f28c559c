#include "core/progress.h"

#include <cstdio>

#include <fmt/format.h>
#include <unistd.h>

namespace veduta {

std::string formatDuration(double seconds) {
    auto s = int64_t(seconds + 0.5);
    if (s < 60) return fmt::format("{}s", s);
    if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
    return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

Progress::Progress(std::string stage, uint64_t total, std::string unit, bool enabled) :
    stage_(std::move(stage)),
    unit_(std::move(unit)),
    total_(total),
    enabled_(enabled && isatty(STDERR_FILENO)),
    start_(std::chrono::steady_clock::now()),
    lastDraw_(start_) {}

Progress::~Progress() { finish(); }

void Progress::advance(uint64_t count) {
    uint64_t done = done_.fetch_add(count) + count;
    if (!enabled_) return;
    auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(drawMutex_, std::try_to_lock);
    if (!lock || now - lastDraw_ < std::chrono::milliseconds(200)) return;
    lastDraw_ = now;
    draw(done, false);
}

void Progress::finish() {
    if (!enabled_ || finished_) return;
    std::lock_guard lock(drawMutex_);
    finished_ = true;
    draw(done_.load(), true);
}

void Progress::draw(uint64_t done, bool final) {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    double fraction = total_ ? double(done) / double(total_) : 1.0;
    std::string eta = final ? "done in " + formatDuration(elapsed)
                            : (done ? "ETA " + formatDuration(elapsed * (1 - fraction) / fraction) : "ETA --");
    double rate = elapsed > 0 ? double(done) / elapsed : 0;
    constexpr int kBarWidth = 30;
    int filled = int(fraction * kBarWidth);
    std::string bar = std::string(size_t(filled), '#') + std::string(size_t(kBarWidth - filled), '.');
    std::fprintf(stderr, "\r%s [%s] %3d%%  %llu/%llu %s  %.1f %s/s  %s\033[K%s", stage_.c_str(), bar.c_str(),
                 int(fraction * 100), (unsigned long long)done, (unsigned long long)total_, unit_.c_str(), rate,
                 unit_.c_str(), eta.c_str(), final ? "\n" : "");
    std::fflush(stderr);
}

}  // namespace veduta
