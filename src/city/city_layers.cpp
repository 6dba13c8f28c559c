#include "city/city_layers.h"

#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "core/atomic_file.h"
#include "io/gdal_messages.h"

namespace veduta {

namespace {

bool isGeoPackage(const std::filesystem::path &target) { return target.extension() == ".gpkg"; }

// A field of a layer: its name and type.
using Field = std::pair<const char *, OGRFieldType>;

// A dataset GDAL writes to `path`, closed (and so flushed) by finish().
class LayerFile {
  public:
    LayerFile(const std::filesystem::path &path, const std::filesystem::path &target, const CityLayersFrame &frame) :
        target_(target) {
        registerGdalDrivers();
        GDALDriver *driver = GetGDALDriverManager()->GetDriverByName(isGeoPackage(target) ? "GPKG" : "GeoJSON");
        if (!driver) fail("GDAL has no driver for this format");
        dataset_.reset(driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
        if (!dataset_) fail("GDAL cannot create it");
        if (frame.epsg != 0) {
            srs_.importFromEPSG(frame.epsg);
            srs_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        }
        epsg_ = frame.epsg;
    }

    OGRLayer *addLayer(const char *name, OGRwkbGeometryType type, const std::vector<Field> &fields) {
        char **options = nullptr;
        // Metres to 0.1 mm, not GeoJSON's 15 significant digits of float noise.
        if (!isGeoPackage(target_)) options = CSLSetNameValue(options, "COORDINATE_PRECISION", "4");
        OGRLayer *layer = dataset_->CreateLayer(name, epsg_ != 0 ? &srs_ : nullptr, type, options);
        CSLDestroy(options);
        if (!layer) fail(fmt::format("GDAL cannot create the layer {}", name));
        for (const auto &[fieldName, fieldType] : fields) {
            OGRFieldDefn field(fieldName, fieldType);
            if (layer->CreateField(&field) != OGRERR_NONE) fail(fmt::format("GDAL cannot add the field {}", fieldName));
        }
        return layer;
    }

    void add(OGRLayer *layer, OGRFeature &feature) {
        if (layer->CreateFeature(&feature) != OGRERR_NONE) fail("GDAL cannot write a feature");
    }

    // GDAL 3.6's close says nothing back but what it reports.
    void finish() {
        GDALClose(GDALDataset::ToHandle(dataset_.release()));
        if (!messages_.failures.empty()) fail("GDAL cannot finish it");
    }

    [[noreturn]] void fail(const std::string &what) const {
        throw std::runtime_error(fmt::format("cannot write {}: {}{}", target_.string(), what, messages_.detail()));
    }

  private:
    GdalMessages messages_;
    std::filesystem::path target_;
    GDALDatasetUniquePtr dataset_;
    OGRSpatialReference srs_;
    int epsg_ = 0;
};

Field field(const char *name, OGRFieldType type) { return {name, type}; }

OGRPolygon polygonOf(const std::vector<Vec2f> &points, const MapOffset &offset) {
    OGRLinearRing ring;
    for (const Vec2f &p : points) ring.addPoint(offset.east + p.x, offset.north + p.y);
    ring.closeRings();
    OGRPolygon polygon;
    polygon.addRing(&ring);
    return polygon;
}

void writeStreets(LayerFile &file, const CityData &city, const MapOffset &offset) {
    OGRLayer *layer = file.addLayer(
        "streets", wkbLineString,
        {field("id", OFTInteger64), field("start", OFTInteger64), field("end", OFTInteger64), field("width", OFTReal)});
    for (const CityStreet &s : city.streets) {
        const CityPoint &a = city.points.at(s.start), &b = city.points.at(s.end);
        OGRFeature feature(layer->GetLayerDefn());
        feature.SetField("id", GIntBig(s.id));
        feature.SetField("start", GIntBig(a.id));
        feature.SetField("end", GIntBig(b.id));
        feature.SetField("width", double(s.width.value_or(city.streetWidth)));
        OGRLineString line;
        line.addPoint(offset.east + a.e, offset.north + a.n);
        line.addPoint(offset.east + b.e, offset.north + b.n);
        feature.SetGeometry(&line);
        file.add(layer, feature);
    }
}

void writeBlocks(LayerFile &file, const CityData &city, const MapOffset &offset) {
    OGRLayer *layer = file.addLayer("blocks", wkbPolygon, {field("id", OFTInteger64), field("area", OFTReal)});
    for (const CityBlock &block : city.blocks) {
        OGRFeature feature(layer->GetLayerDefn());
        OGRPolygon polygon = polygonOf(block.points, offset);
        feature.SetField("id", GIntBig(block.sourceId));
        feature.SetField("area", polygon.get_Area());
        feature.SetGeometry(&polygon);
        file.add(layer, feature);
    }
}

std::string streetEdgesText(const std::vector<bool> &streetEdges) {
    std::vector<size_t> edges;
    for (size_t i = 0; i < streetEdges.size(); ++i)
        if (streetEdges[i]) edges.push_back(i);
    return fmt::format("{}", fmt::join(edges, " "));
}

void writeLots(LayerFile &file, const CityData &city, const MapOffset &offset) {
    OGRLayer *layer = file.addLayer("lots", wkbPolygon,
                                    {field("block", OFTInteger64), field("lot", OFTInteger), field("id", OFTInteger64),
                                     field("area", OFTReal), field("street_edges", OFTString)});
    for (const CityBlock &block : city.blocks)
        for (size_t l = 0; l < block.lots.size(); ++l) {
            const CityLot &lot = block.lots[l];
            OGRFeature feature(layer->GetLayerDefn());
            OGRPolygon polygon = polygonOf(lot.points, offset);
            feature.SetField("block", GIntBig(block.sourceId));
            feature.SetField("lot", int(l));
            feature.SetField("id", GIntBig(lot.sourceId));
            feature.SetField("area", polygon.get_Area());
            feature.SetField("street_edges", streetEdgesText(lot.streetEdges).c_str());
            feature.SetGeometry(&polygon);
            file.add(layer, feature);
        }
}

using LayerWriter = void (*)(LayerFile &, const CityData &, const MapOffset &);

}  // namespace

std::vector<std::filesystem::path> cityLayerFiles(const std::filesystem::path &target) {
    if (isGeoPackage(target)) return {target};
    return {target / "streets.geojson", target / "blocks.geojson", target / "lots.geojson"};
}

void writeCityLayers(const CityData &city, const CityLayersFrame &frame, const std::filesystem::path &target) {
    const LayerWriter writers[] = {writeStreets, writeBlocks, writeLots};
    std::vector<std::filesystem::path> files = cityLayerFiles(target);
    if (isGeoPackage(target)) {
        writeFileAtomically(target, [&](const std::filesystem::path &temporary) {
            LayerFile file(temporary, target, frame);
            for (LayerWriter write : writers) write(file, city, frame.offset);
            file.finish();
        });
        return;
    }
    for (size_t i = 0; i < files.size(); ++i)
        writeFileAtomically(files[i], [&](const std::filesystem::path &temporary) {
            LayerFile file(temporary, files[i], frame);
            writers[i](file, city, frame.offset);
            file.finish();
        });
}

}  // namespace veduta
