#include "report_page.h"

#include "html_text.h"

namespace cordgrasp {
namespace {

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; color: #222; max-width: 1200px; margin: 1.5em auto;
       padding: 0 1em; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: left; }
th { background: #f2f2f2; }
td.num { text-align: right; white-space: nowrap; }
td.held { background: #dff2df; } td.slipped { background: #fcefd2; }
td.dropped, td.unstable { background: #f8dcdc; } td.not-run { color: #888; }
.warning { background: #fff3cd; border: 1px solid #e0c36a; padding: 0.5em; }
.note, figcaption { color: #555; font-size: 90%; }
section.grasp { border-top: 2px solid #ddd; margin-top: 1.5em; }
figure { display: inline-block; vertical-align: top; margin: 0 1em 1em 0; }
figure img { border: 1px solid #ddd; max-width: 100%; }
img.picture, img.animation { width: 480px; }
.viewer { width: 480px; height: 360px; border: 1px solid #ddd; background: #fafafa; }
.viewer canvas { display: block; cursor: grab; }
#selftest { white-space: pre-wrap; font-size: 80%; }
</style>
)";

/// First in <head>: records script errors, failed loads and console.error calls for the
/// self-test, before any other script runs.
constexpr const char* kErrorCapture = R"(<script>
window.cordgraspErrors = [];
window.addEventListener("error", function (e) {
  var t = e.target;
  window.cordgraspErrors.push(t && t !== window && (t.src || t.href)
      ? "failed to load " + (t.src || t.href) : String(e.message));
}, true);
window.addEventListener("unhandledrejection", function (e) {
  window.cordgraspErrors.push("unhandled rejection: " + e.reason);
});
(function () {
  var error = console.error;
  console.error = function () {
    window.cordgraspErrors.push(Array.prototype.join.call(arguments, " "));
    error.apply(console, arguments);
  };
})();
</script>
)";

/// Last in <body>: a three.js view in every `.viewer[data-model]` (turned, zoomed and moved
/// with the mouse; drawn on demand), and the self-test cordgraspSelftest().
constexpr const char* kViewerScript = R"(<script>
(function () {
  var background = 0xfafafa;
  function buffer(base64) {
    var text = atob(base64), bytes = new Uint8Array(text.length);
    for (var i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    return bytes.buffer;
  }
  function makeView(div) {
    var name = div.getAttribute("data-model");
    var models = window.cordgraspModels || {};
    if (!window.THREE || !THREE.GLTFLoader || !THREE.OrbitControls || !models[name]) {
      div.textContent = "3D view unavailable: its scripts did not load.";
      return Promise.reject(new Error("3D view of " + name + ": scripts did not load"));
    }
    var w = div.clientWidth, h = div.clientHeight;
    var renderer = new THREE.WebGLRenderer({ antialias: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(w, h);
    renderer.setClearColor(background);
    div.appendChild(renderer.domElement);
    var scene = new THREE.Scene();
    scene.add(new THREE.HemisphereLight(0xffffff, 0x555555, 0.8));
    var camera = new THREE.PerspectiveCamera(35, w / h, 0.001, 100);
    camera.up.set(0, 0, 1);  // the object frame's z up
    var headlight = new THREE.DirectionalLight(0xffffff, 0.6);
    headlight.position.set(0.5, 1, 1);
    camera.add(headlight);
    scene.add(camera);
    var controls = new THREE.OrbitControls(camera, renderer.domElement);
    var view = { name: name, renderer: renderer, background: background,
                 render: function () { renderer.render(scene, camera); } };
    controls.addEventListener("change", view.render);
    return new Promise(function (resolve, reject) {
      new THREE.GLTFLoader().parse(buffer(models[name]), "", function (gltf) {
        gltf.scene.traverse(function (o) {  // the export gives colours only: matte
          if (o.isMesh) { o.material.metalness = 0; o.material.roughness = 0.8; }
        });
        scene.add(gltf.scene);
        var box = new THREE.Box3().setFromObject(gltf.scene);
        var centre = box.getCenter(new THREE.Vector3());
        var radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
        var distance = 0.85 * radius / Math.sin(camera.fov / 2 * Math.PI / 180);
        camera.position.copy(centre).add(
            new THREE.Vector3(1, -1.3, 0.9).normalize().multiplyScalar(distance));
        camera.near = distance / 100;
        camera.far = distance * 100;
        camera.updateProjectionMatrix();
        controls.target.copy(centre);
        controls.update();
        view.render();
        resolve(view);
      }, function (e) { reject(new Error("3D view of " + name + ": " + e)); });
    });
  }
  var divs = Array.prototype.slice.call(document.querySelectorAll(".viewer[data-model]"));
  var views = Promise.all(divs.map(function (div) {
    return makeView(div).catch(function (e) { console.error(String(e)); return null; });
  }));
  // Self-test: every image decodes, every 3D view draws, no error. Resolves to
  // { images: [{src, ok}], views: [{model, pixels, drawn}], errors: [...] }.
  window.cordgraspSelftest = function () {
    var images = Array.prototype.slice.call(document.images);
    var result = { images: [], views: [], errors: [] };
    return Promise.all(images.map(function (img) {
      return img.decode().then(function () { return img.naturalWidth > 0; },
                               function () { return false; })
          .then(function (ok) { result.images.push({ src: img.getAttribute("src"), ok: ok }); });
    })).then(function () { return views; }).then(function (list) {
      list.forEach(function (view) {
        if (!view) return;
        view.render();  // read back before the buffer is presented and cleared
        var gl = view.renderer.getContext();
        var w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
        var pixels = new Uint8Array(w * h * 4);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        var bg = [(view.background >> 16) & 255, (view.background >> 8) & 255,
                  view.background & 255], drawn = 0;
        for (var i = 0; i < pixels.length; i += 4)
          if (Math.abs(pixels[i] - bg[0]) + Math.abs(pixels[i + 1] - bg[1]) +
              Math.abs(pixels[i + 2] - bg[2]) > 24) ++drawn;
        result.views.push({ model: view.name, pixels: w * h, drawn: drawn });
      });
    }).catch(function (e) { result.errors.push("self-test: " + e); }).then(function () {
      result.errors = result.errors.concat(window.cordgraspErrors);
      return result;
    });
  };
  // report.html?selftest: the result as JSON in #selftest once the page has loaded.
  if (/[?&]selftest\b/.test(location.search))
    window.addEventListener("load", function () {
      window.cordgraspSelftest().then(function (result) {
        document.getElementById("selftest").textContent = JSON.stringify(result);
      });
    });
})();
</script>
)";

}  // namespace

std::string report_page_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         html_escaped(title) + "</title>\n" + kErrorCapture + kStyle + "</head>\n<body>\n<h1>" +
         html_escaped(title) + "</h1>\n";
}

std::string report_page_tail() {
  return std::string("<pre id=\"selftest\"></pre>\n") + kViewerScript + "</body>\n</html>\n";
}

}  // namespace cordgrasp
