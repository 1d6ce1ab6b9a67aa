set -e
BUILD_DIR=/var/raylab/build bash .ci/setup > /src/raylab/.d13out-build.log 2>&1
B=/var/raylab/build/raylab
mkdir -p /src/raylab/.d13out/bench
for bvh in binary sbvh wide; do
  $B render --scene temple --view hall --size 512x256 --frames 4 --bvh $bvh --out /src/raylab/.d13out/hall-$bvh.png > /dev/null 2>&1
  $B render --scene /src/shared/scenes/Sponza/Sponza.gltf --view CameraMain --size 512x256 --frames 4 --bvh $bvh --out /src/raylab/.d13out/sponza-$bvh.png > /dev/null 2>&1
done
$B bench --cases "/src/shared/scenes/Sponza/Sponza.gltf@CameraMain,temple@hall" --sizes 512x256 --bounces 4 --bvhs binary,sbvh,wide --strategies two-point --rounds 2 --timed-frames 4 --warmup 1 --reference-spp 4 --no-detail --no-charts --out-dir /src/raylab/.d13out/bench > /src/raylab/.d13out/bench.log 2>&1
echo d13done
