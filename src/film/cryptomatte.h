// Cryptomatte (Psyop's specification 1.1, as Blender's compositor and Nuke's gizmo read it): per
// pixel the ids of the objects (materials) its camera samples met first, ranked by coverage, the
// share of the pixel's samples that met each. An id is MurmurHash3 of a name stored as a float's
// bits; the header names each type and maps names to ids in a JSON manifest. docs/output.md,
// "Cryptomatte", says what veduta writes and what merging keeps.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/layered_image.h"
#include "scene/render_scene.h"

namespace veduta {

enum class CryptomatteKind { Object, Material };
inline constexpr CryptomatteKind kCryptomatteKinds[] = {CryptomatteKind::Object, CryptomatteKind::Material};
// The specification's suggested default: three layers of two ranks each.
inline constexpr int kDefaultCryptomatteRanks = 6;
inline constexpr int kMaxCryptomatteRanks = 16;

// "CryptoObject" or "CryptoMaterial": the pass, whose layers are "<pass>00", "<pass>01", …
const char *cryptomattePass(CryptomatteKind kind);
// "ViewLayer.CryptoObject" …: the type name in the header, as Blender writes it.
std::string cryptomatteTypeName(CryptomatteKind kind);
// "cryptomatte/<first 7 hex digits of the type name's hash>/", the type's metadata prefix.
std::string cryptomatteMetadataPrefix(const std::string &typeName);
// Layers holding `ranks` ranks: two per layer.
int cryptomatteLayers(int ranks);
// The channel of rank `rank`'s id (coverage: true, its coverage) in the pass's layers,
// e.g. "ViewLayer.CryptoObject00.R".
std::string cryptomatteChannel(CryptomatteKind kind, int rank, bool coverage);
// Whether a channel belongs to a Cryptomatte layer (of either kind).
bool isCryptomatteChannel(std::string_view channel);

// MurmurHash3 of the name with the exponent clamped to [1, 254], so that no id is a denormal,
// an infinity or a NaN; stored as a float with these bits.
uint32_t cryptomatteIdBits(std::string_view name);
float cryptomatteId(std::string_view name);
// The manifest's spelling of an id: its float's bits as 8 lowercase hex digits.
std::string cryptomatteHex(uint32_t idBits);

// The film's key of the object a first hit met: its building and object ids. A material's key
// is its film material id.
uint64_t cryptomatteObjectKey(ObjectId objectId, uint32_t buildingId);
// What a film key stands for, by name.
using CryptomatteNaming = std::function<std::string(CryptomatteKind kind, uint64_t key)>;
// Objects by their stable names (scene/object_names.h), materials by the scene's names.
CryptomatteNaming cryptomatteNaming(const RenderScene &scene);

// One id's share of a pixel: `weight` in samples (exact integers), ranked by weight.
struct CryptomatteEntry {
    uint32_t idBits = 0;
    double weight = 0;
};
// The entries in rank order: weight descending, ties by id, so that any order of accumulation
// gives the same ranks; at most `ranks` of them.
std::vector<CryptomatteEntry> rankEntries(std::vector<CryptomatteEntry> entries, int ranks);

// The pass's layers in `image` for `ranks` ranks, zero-filled, and its header entries.
void addCryptomatteLayers(LayeredImage &image, CryptomatteKind kind, int ranks,
                          const std::map<std::string, std::string> &manifest);
// The channels of the kind's ranks in `image`: id and coverage of rank 0, of rank 1, … Taken
// once every channel is added.
std::vector<std::vector<float> *> rankChannels(LayeredImage &image, CryptomatteKind kind);
std::vector<const std::vector<float> *> rankChannels(const LayeredImage &image, CryptomatteKind kind);
// Writes a pixel's ranked entries, coverage = weight / samples.
void storeRanks(const std::vector<std::vector<float> *> &channels, size_t pixel,
                const std::vector<CryptomatteEntry> &ranked, double samples);
// The ranks stored at a pixel, weights = coverage × samples rounded to whole samples, which is
// exact for fewer than 2^24 samples.
std::vector<CryptomatteEntry> readRanks(const std::vector<const std::vector<float> *> &channels, size_t pixel,
                                        double samples);
// How many ranks `image` holds of the kind (0: none).
int storedRanks(const LayeredImage &image, CryptomatteKind kind);

// The manifest {name: hex} as JSON, and back: one object of string members, with JSON's escapes;
// parseManifest throws std::runtime_error for anything else.
std::string manifestJson(const std::map<std::string, std::string> &manifest);
std::map<std::string, std::string> parseManifest(const std::string &json);
// The manifest stored in the image's header for the kind (empty if none).
std::map<std::string, std::string> storedManifest(const LayeredImage &image, CryptomatteKind kind);

}  // namespace veduta
