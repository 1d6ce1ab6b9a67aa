#include "app/cli_options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>

#include "renderer/settings_validation.h"

namespace raylab {

// Range checks and their wording are settings_validation's, shared with sidecars, scripts and imgui.ini.
uint32_t parseUint(const std::string& flag, const std::string& text, uint32_t lo, uint32_t hi) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw UsageError(flag + " expects a whole number, got '" + text + "'");
  errno = 0;
  unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v < lo || v > hi)
    throw UsageError(outOfRangeMessage({flag.c_str(), double(lo), double(hi)}, text));
  return static_cast<uint32_t>(v);
}

float parseFloat(const std::string& flag, const std::string& text, float lo, float hi) {
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    throw UsageError(flag + " expects a finite number, got '" + text + "'");
  try {
    checkFloat({flag.c_str(), lo, hi}, v, text);  // compared as floats: the limits themselves are accepted
  } catch (const SettingsError& e) {
    throw UsageError(e.what());
  }
  return static_cast<float>(v);
}

namespace {

using L = SettingLimits;

void parseSize(const std::string& text, Settings& s) {
  size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError("--size expects WxH (e.g. 512x256), got '" + text + "'");
  s.width = parseUint("--size width", text.substr(0, x), 1, L::kMaxSize);
  s.height = parseUint("--size height", text.substr(x + 1), 1, L::kMaxSize);
}

void parseGrid(const std::string& text, Settings& s) {
  if (text == "auto") {
    s.grid.automatic = true;
    return;
  }
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t x; (x = text.find('x', start)) != std::string::npos; start = x + 1) parts.push_back(text.substr(start, x - start));
  parts.push_back(text.substr(start));
  if (parts.size() != 1 && parts.size() != 3) throw UsageError("--grid expects auto, N or NXxNYxNZ, got '" + text + "'");
  s.grid.automatic = false;
  for (int a = 0; a < 3; ++a)
    s.grid.cells[a] = parseUint("--grid", parts[parts.size() == 1 ? 0 : a], 1, L::kMaxGridCellsPerAxis);
}

template <class E>
E parseEnum(const std::string& flag, const std::string& text, std::optional<E> (*parse)(const std::string&),
            const std::string& accepted) {
  std::optional<E> v = parse(text);
  if (!v) throw UsageError(flag + " must be one of " + accepted + ", got '" + text + "'");
  return *v;
}

// "auto" (each frame's own range) or "MIN:MAX" (locked); the interval is checked as every source's is.
void parseHeatmapRange(const std::string& text, Settings& s) {
  if (text == "auto") {
    s.heatmapRange.locked = false;
    return;
  }
  size_t colon = text.find(':');
  if (colon == std::string::npos) throw UsageError("--heatmap-range expects auto or MIN:MAX (e.g. 0:200), got '" + text + "'");
  HeatmapRange r{true, parseFloat("--heatmap-range min", text.substr(0, colon), 0.0f, L::kMaxHeatmapValue),
                 parseFloat("--heatmap-range max", text.substr(colon + 1), 0.0f, L::kMaxHeatmapValue)};
  try {
    checkHeatmapRange(r);
  } catch (const SettingsError& e) {
    throw UsageError(e.what());
  }
  s.heatmapRange = r;
}

}  // namespace

CommonOptions parseCommonOptions(const std::vector<std::string>& args, std::vector<std::string>* rest) {
  CommonOptions o;
  Settings& s = o.settings;
  using Handler = std::function<void(const std::string&)>;
  const std::map<std::string, Handler> valued = {
      {"--scene", [&](const std::string& v) { s.scene = v; }},
      {"--view", [&](const std::string& v) { s.view = v; }},
      {"--size", [&](const std::string& v) { parseSize(v, s); }},
      {"--bounces", [&](const std::string& v) { s.bounces = parseUint("--bounces", v, 1, L::kMaxBounces); }},
      {"--spp", [&](const std::string& v) { s.sppPerFrame = parseUint("--spp", v, 1, L::kMaxSpp); }},
      {"--frames", [&](const std::string& v) { s.frames = parseUint("--frames", v, 1, L::kMaxFrames); }},
      {"--seed", [&](const std::string& v) { s.seed = parseUint("--seed", v, 0, UINT32_MAX); }},
      {"--exposure", [&](const std::string& v) { s.exposure = parseFloat("--exposure", v, 0.0f, L::kMaxExposure); }},
      {"--kernel", [&](const std::string& v) { s.kernel = parseEnum("--kernel", v, &parseKernel, "wavefront|megakernel"); }},
      {"--tracer", [&](const std::string& v) { s.tracer = parseEnum("--tracer", v, &parseTracer, "compute|rt"); }},
      {"--bvh", [&](const std::string& v) { s.bvh = parseEnum("--bvh", v, &parseBvhLayout, "binary|wide"); }},
      {"--ser", [&](const std::string& v) { s.ser = parseEnum("--ser", v, &parseSer, "off|on|hint"); }},
      {"--strategy", [&](const std::string& v) { s.strategy = parseEnum("--strategy", v, &parseKeyStrategy, keyStrategyNames()); }},
      {"--sort", [&](const std::string& v) { s.sort = parseEnum("--sort", v, &parseSortAlgorithm, "none|bitonic|radix|tile"); }},
      {"--sort-policy", [&](const std::string& v) { s.sortPolicy = parseEnum("--sort-policy", v, &parseSortPolicy, "always|never|auto"); }},
      {"--sort-bits", [&](const std::string& v) { s.sortBits = parseUint("--sort-bits", v, 0, 32); }},
      {"--fusion", [&](const std::string& v) { s.fusion = parseEnum("--fusion", v, &parseFusion, "none|keys|gather|both"); }},
      {"--compaction", [&](const std::string& v) { s.compaction = parseEnum("--compaction", v, &parseCompaction, "none|shade"); }},
      {"--trace-shade", [&](const std::string& v) { s.traceShade = parseEnum("--trace-shade", v, &parseTraceShade, "split|fused"); }},
      {"--learn-every", [&](const std::string& v) { s.learnEvery = parseUint("--learn-every", v, 1, 64); }},
      {"--grid", [&](const std::string& v) { parseGrid(v, s); }},
      {"--clamp", [&](const std::string& v) {
         s.clampToCamera = true;
         s.clampDistance = parseFloat("--clamp", v, 0.0f, L::kMaxClampDistance);
       }},
      {"--fixed-factor", [&](const std::string& v) { s.fixedFactor = parseFloat("--fixed-factor", v, L::kMinFixedFactor, L::kMaxFixedFactor); }},
      {"--ema-alpha", [&](const std::string& v) { s.emaAlpha = parseFloat("--ema-alpha", v, L::kMinEmaAlpha, L::kMaxEmaAlpha); }},
      {"--gauss-outlier", [&](const std::string& v) { s.gaussOutlier = parseFloat("--gauss-outlier", v, 0.0f, L::kMaxGaussOutlier); }},
      {"--gauss-reset", [&](const std::string& v) {
         s.gaussReset = v == "inf" ? INFINITY : parseFloat("--gauss-reset", v, 0.0f, 3.0e38f);
       }},
      {"--heatmap", [&](const std::string& v) {
         s.heatmap = parseEnum("--heatmap", v, &parseHeatmapView,
                               "none|sort-key|cell-hit|traversal-steps|warp-efficiency|cache-mean|cache-variance");
       }},
      {"--heatmap-bounce", [&](const std::string& v) { s.heatmapBounce = parseUint("--heatmap-bounce", v, 0, L::kMaxBounces - 1); }},
      {"--heatmap-key-colour", [&](const std::string& v) {
         s.heatmapKeyColour = parseEnum("--heatmap-key-colour", v, &parseHeatmapKeyColour, "cell|rank|hash");
       }},
      {"--heatmap-scale", [&](const std::string& v) { s.heatmapScale = parseEnum("--heatmap-scale", v, &parseHeatmapScale, "linear|log"); }},
      {"--heatmap-range", [&](const std::string& v) { parseHeatmapRange(v, s); }},
      {"--device", [&](const std::string& v) { o.device = v; }},
      {"--out", [&](const std::string& v) { o.out = v; }},
      {"--stats", [&](const std::string& v) { o.statsPath = v; }},
  };
  const std::map<std::string, std::function<void()>> switches = {
      {"--validate", [&] { o.validation = ValidationMode::Sync; }},
      {"--validate=sync", [&] { o.validation = ValidationMode::Sync; }},
      {"--validate=gpu-av", [&] { o.validation = ValidationMode::GpuAssisted; }},
      {"--count-simt", [&] { s.countSimt = true; }},
  };
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (auto it = valued.find(a); it != valued.end()) {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      it->second(args[++i]);
    } else if (auto sw = switches.find(a); sw != switches.end()) {
      sw->second();
    } else if (rest && a.rfind("--", 0) == 0) {
      rest->push_back(a);
      if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) rest->push_back(args[++i]);
    } else {
      throw UsageError("unknown option '" + a + "'");
    }
  }
  // What no single flag can check (paths per frame) and every range once more, as for any other source.
  if (std::optional<std::string> error = settingsError(s)) throw UsageError(*error);
  return o;
}

std::string commonOptionsHelp() {
  return "  --scene temple|cornell|furnace|temple-detail:N|FILE.gltf|FILE.glb   scene (default temple;\n"
         "                         temple-detail:N is the temple with N triangles, 1e4 to 3e7)\n"
         "  --view NAME            viewpoint (default: the scene's first)\n"
         "  --size WxH             resolution, any size up to 8192x8192 (default 512x256)\n"
         "  --bounces N            path length in bounces, 1..32 (default 4)\n"
         "  --spp N                samples per pixel per frame, 1..64 (default 1)\n"
         "  --frames N             frames to accumulate (default 1)\n"
         "  --seed N               random seed (default 1)\n"
         "  --kernel wavefront|megakernel\n"
         "  --tracer compute|rt    our BVH in compute shaders (default), or VK_KHR_ray_tracing_pipeline\n"
         "  --bvh binary|wide      compute tracer: the binary BVH (default) or the compressed 8-wide one\n"
         "                         collapsed from it (quantized child boxes, as CWBVH)\n"
         "  --ser off|on|hint      rt megakernel: Shader Execution Reordering by hit, or by hit with the\n"
         "                         top bits of --strategy's key as coherence hint (needs a strategy)\n"
         "  --strategy " + keyStrategyNames() + "\n"
         "  --sort none|bitonic|radix|tile  sort used when a strategy is set (default radix); tile sorts\n"
         "                         each 2048 paths alone (needs --compaction shade)\n"
         "  --sort-policy always|never|auto  which bounces sort: all, none, or where earlier frames measured\n"
         "                         a saving (default always)\n"
         "  --sort-bits N          order only the key's top N bits, 0..32 (default 0: all); 8 bits\n"
         "                         fewer is one radix pass less\n"
         "  --fusion none|keys|gather|both  compute wavefront: keys made in shade, the reorder done by the\n"
         "                         next trace (same image; default gather)\n"
         "  --compaction none|shade  compute wavefront: shade packs the live paths at the front of the\n"
         "                         other state set, so later stages visit only live paths (same\n"
         "                         image; default shade)\n"
         "  --trace-shade split|fused  compute wavefront: trace and shade of a bounce as two dispatches\n"
         "                         (default) or one where nothing reads the hit between them (same image)\n"
         "  --grid auto|N|NXxNYxNZ  key grid (default auto, 64 cells on the largest axis)\n"
         "  --clamp D              clamp the key grid to camera +- D\n"
         "  --fixed-factor F       fixed length = F * largest extent (default 0.5; Meister et al. 0.25)\n"
         "  --ema-alpha A          EMA weight of a new length (default 0.2)\n"
         "  --gauss-outlier S      reject lengths beyond S sigmas (default 3)\n"
         "  --gauss-reset V        reset a cell when its variance exceeds V (default 20, 'inf' never)\n"
         "  --learn-every N        length caches learn from every N-th sorted ray, 1..64 (default 1)\n"
         "  --exposure E           display exposure (default 1)\n"
         "  --heatmap VIEW         show sort-key|cell-hit|traversal-steps|warp-efficiency|cache-mean|\n"
         "                         cache-variance per pixel instead of the render\n"
         "  --heatmap-bounce N     bounce the heatmap shows (default 1; 0 = camera rays)\n"
         "  --heatmap-key-colour cell|rank|hash  sort-key colours: the key's grid cell as a position colour\n"
         "                         (default), its rank among the sorted keys, or a hash (equal keys alike)\n"
         "  --heatmap-scale linear|log  value to colour mapping of scalar heatmaps (default linear)\n"
         "  --heatmap-range auto|MIN:MAX  colour range of scalar heatmaps: each frame's own (default;\n"
         "                         warp-efficiency 0..1), or locked to MIN..MAX\n"
         "  --count-simt           count active subgroup lanes in traversal (slower; not for timing)\n"
         "  --device NAME          Vulkan device whose name contains NAME\n"
         "  --validate[=sync|gpu-av]  enable the Khronos validation layer: core and synchronization\n"
         "                         checks (sync, the default), or core and GPU-assisted checks of\n"
         "                         every buffer-device-address access (gpu-av; slow); exit 4 on an\n"
         "                         error. RAYLAB_VALIDATE=1|sync|gpu-av does the same\n"
         "  --settings FILE.json   start from a screenshot sidecar (its settings and camera)\n"
         "  --out FILE.png         output image\n"
         "  --stats FILE.json      per-frame statistics as JSON\n";
}

}  // namespace raylab
