#include "geodesy/datum_grid.h"

#include <cmath>

#include <proj.h>

namespace veduta {

namespace {

constexpr double kRadian = M_PI / 180;

// PROJ objects are not shared between threads, so every thread opens the grid once.
class GridShift {
  public:
    GridShift() : context_(proj_context_create()) {
        proj_log_level(context_, PJ_LOG_NONE);  // a missing grid is told by beta2007Installed
        shift_ = proj_create(context_, "+proj=hgridshift +grids=BETA2007.gsb");
    }
    ~GridShift() {
        if (shift_) proj_destroy(shift_);
        proj_context_destroy(context_);
    }
    GridShift(const GridShift &) = delete;
    GridShift &operator=(const GridShift &) = delete;

    bool installed() const { return shift_ != nullptr; }

    std::optional<GeographicPoint> apply(PJ_DIRECTION direction, const GeographicPoint &p) const {
        if (!shift_) return std::nullopt;
        PJ_COORD out = proj_trans(shift_, direction, proj_coord(p.longitude * kRadian, p.latitude * kRadian, 0, 0));
        if (!std::isfinite(out.lp.lam) || !std::isfinite(out.lp.phi)) {
            proj_errno_reset(shift_);
            return std::nullopt;
        }
        return GeographicPoint{out.lp.phi / kRadian, out.lp.lam / kRadian};
    }

  private:
    PJ_CONTEXT *context_;
    PJ *shift_ = nullptr;
};

const GridShift &gridShift() {
    thread_local const GridShift shift;
    return shift;
}

}  // namespace

bool beta2007Installed() { return gridShift().installed(); }

std::optional<GeographicPoint> beta2007DhdnToEtrs89(const GeographicPoint &dhdn) {
    return gridShift().apply(PJ_FWD, dhdn);
}

std::optional<GeographicPoint> beta2007Etrs89ToDhdn(const GeographicPoint &etrs89) {
    return gridShift().apply(PJ_INV, etrs89);
}

}  // namespace veduta
