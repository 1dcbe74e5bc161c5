// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `expmap view`: a web server for the viewer page (tools/viewer/www) and
// its JSON API. cpp-httplib (Debian's libcpp-httplib-dev) keeps the server
// in the library's language and in one small dependency; its thread pool
// answers requests in parallel, so that a slow query of one method does not
// hold the page's queries of another.

#include "View_command.h"

#include "../Command_line.h"
#include "Map_service.h"
#include "Memory_release.h"
#include "Viewer_json.h"

#include <expmap/Errors.h>
#include <expmap/IO/read_triangle_mesh.h>

#include <CGAL/boost/graph/helpers.h>

#include <httplib.h>
#include <zlib.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace expmap_view {

namespace {

namespace fs = std::filesystem;
using expmap_cli::Usage_error;

struct View_arguments {
  std::string mesh;
  std::string host = "127.0.0.1";
  int port = 8765;
  bool help = false;
};

View_arguments parse_view_arguments(const std::vector<std::string>& args) {
  View_arguments a;
  std::vector<std::string> positional;
  bool port_given = false, host_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i], value;
    bool inline_value = false;
    if (name.size() < 2 || name[0] != '-') {
      positional.push_back(name);
      continue;
    }
    const std::string::size_type equals = name.find('=');
    if (name.compare(0, 2, "--") == 0 && equals != std::string::npos) {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
      inline_value = true;
    }
    const auto take_value = [&]() -> std::string {
      if (inline_value) return value;
      if (i + 1 >= args.size()) throw Usage_error(name + " needs a value");
      return args[++i];
    };
    if (name == "-h" || name == "--help") {
      a.help = true;
      return a;
    } else if (name == "--port") {
      expmap_cli::check_once(name, port_given);
      const std::size_t port = expmap_cli::parse_index(name, take_value());
      if (port > 65535) throw Usage_error("--port must be at most 65535 (0: any free port)");
      a.port = static_cast<int>(port);
      port_given = true;
    } else if (name == "--host") {
      expmap_cli::check_once(name, host_given);
      a.host = take_value();
      if (a.host.empty()) throw Usage_error("--host needs an address");
      host_given = true;
    } else {
      throw Usage_error("unknown option '" + name + "' (see expmap view --help)");
    }
  }
  if (positional.empty()) throw Usage_error("no mesh file given (see expmap view --help)");
  if (positional.size() > 1)
    throw Usage_error("more than one mesh file given ('" + positional[0] + "', '" + positional[1] +
                      "')");
  a.mesh = positional[0];
  return a;
}

// A response body, with its gzip form when it is worth one (the page's
// files and the mesh, made once at start).
struct Body {
  std::string content, gzip, mime;
};

// `text` in gzip form, at zlib's fastest level: the mesh's JSON on 2.85M
// vertices (303 MB) compresses to 124 MB in about 5 s; the default level
// takes five times as long for a few percent fewer bytes.
std::string gzip(const std::string& text) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_SPEED, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib cannot start compressing");
  std::string out(deflateBound(&z, static_cast<uLong>(text.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("zlib could not compress a response");
  return out;
}

Body make_body(std::string content, std::string mime) {
  Body b{std::move(content), "", std::move(mime)};
  if (b.content.size() > 1024) b.gzip = gzip(b.content);
  return b;
}

// Sends `body` as it is, or in gzip form where the client takes it. The
// body goes out through a content provider of known length, which the HTTP
// library sends unchanged: left to itself it would compress every text
// response on every request, with Brotli at its slowest setting (hundreds of
// milliseconds for a map).
void send(httplib::Response& res, int status, const std::shared_ptr<const Body>& body,
          const httplib::Request& req) {
  res.status = status;
  const bool zipped = !body->gzip.empty() &&
                      req.get_header_value("Accept-Encoding").find("gzip") != std::string::npos;
  const std::string& bytes = zipped ? body->gzip : body->content;
  if (zipped) res.set_header("Content-Encoding", "gzip");
  res.set_content_provider(bytes.size(), body->mime,
                           [body, &bytes](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             return sink.write(bytes.data() + offset, length);
                           });
}

// Sends `json`; with `release`, gives the memory it and its map leave free
// back to the system once it is sent (Memory_release.h).
void send_json(httplib::Response& res, int status, std::string json, bool release = false) {
  res.status = status;
  auto body = std::make_shared<const std::string>(std::move(json));
  const std::string* bytes = body.get();
  // The releaser owns the body, so that it is freed before the trim.
  res.set_content_provider(
      body->size(), "application/json",
      [bytes](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
        return sink.write(bytes->data() + offset, length);
      },
      [body, release](bool) mutable {
        body.reset();
        if (release) release_free_memory();
      });
}

std::string mime_type(const fs::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  return "text/plain; charset=utf-8";
}

// The folder of the page: `viewer` beside the program in the build tree,
// `share/expmap/viewer` beside its `bin` once installed.
fs::path page_folder() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path dir = program.parent_path();
    for (const fs::path& candidate : {dir / "viewer", dir.parent_path() / "share" / "expmap" / "viewer"})
      if (fs::is_regular_file(candidate / "index.html", error)) return candidate;
  }
  throw std::runtime_error(
      "cannot find the viewer's page (viewer/index.html beside the program, or "
      "share/expmap/viewer once installed); build the expmap target again");
}

std::map<std::string, std::shared_ptr<const Body>> read_page(const fs::path& folder) {
  std::map<std::string, std::shared_ptr<const Body>> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream content;
    if (in) content << in.rdbuf();
    if (!in || in.bad())
      throw std::runtime_error("cannot read the viewer's file '" + entry.path().string() + "'");
    files["/" + fs::relative(entry.path(), folder).generic_string()] =
        std::make_shared<const Body>(make_body(content.str(), mime_type(entry.path())));
  }
  return files;
}

// Answers `compute()`'s exceptions with the status they stand for;
// `compute()` returns the JSON, and whether to release memory after it.
template <class Compute>
void answer(httplib::Response& res, Compute compute) {
  try {
    std::pair<std::string, bool> json = compute();
    send_json(res, 200, std::move(json.first), json.second);
  } catch (const Too_large& e) {
    send_json(res, 413, too_large_json(e));
  } catch (const Bad_request& e) {
    send_json(res, 400, error_json(e.what()));
  } catch (const expmap::Invalid_input& e) {
    send_json(res, 400, error_json(e.what()));
  } catch (const Precomputation_failed& e) {
    send_json(res, e.invalid_input ? 400 : 422, error_json(e.what()));
  } catch (const Busy& e) {
    res.set_header("Retry-After", std::to_string(e.retry_after));
    send_json(res, 503, error_json(e.what()));
  } catch (const expmap::Computation_error& e) {
    send_json(res, 422, error_json(e.what()));
  } catch (const std::exception& e) {
    send_json(res, 500, error_json(expmap::internal::user_message(e)));
  }
}

// Whether `host` (an address given to --host) is this machine's loopback.
bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

// `host` as the authority of a URL or a Host header names it: an IPv6
// address in brackets.
std::string url_host(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

}  // namespace

std::string view_help() {
  const Cache_limits limits;
  return "usage: expmap view MESH [--port P] [--host H]\n"
         "\n"
         "Serves an interactive view of local exponential maps on MESH in the web\n"
         "browser: click or drag on the surface to place the source, compare two\n"
         "methods side by side. Prints the address to open; Ctrl-C stops it.\n"
         "\n"
         "  MESH        triangle mesh: .off, .obj, .ply or .stl\n"
         "  --port P    the port (default: 8765; 0: any free port)\n"
         "  --host H    the address to listen on (default: 127.0.0.1, this machine\n"
         "              only; the page and its API have no authentication, so give\n"
         "              another address only on a network you trust)\n"
         "  -h, --help  this help\n"
         "\n"
         "API (JSON): GET /api/mesh, GET /api/status, and\n"
         "GET /api/map?point=X,Y,Z&method=M&fraction=F (or radius=R; m=T for heat).\n"
         "Bad parameters get HTTP 400 with {\"error\": \"...\"}, a patch larger than the\n"
         "method's limit HTTP 413 (exact: " + std::to_string(max_exact_patch_vertices) +
         " vertices and " + std::to_string(max_exact_region_faces) + " faces of its submesh;\n"
         "others: " + std::to_string(max_fast_patch_vertices) + " vertices).\n" +
         std::to_string(limits.queries_per_method) + " queries run on a method at once and " +
         std::to_string(limits.waiting_per_method) + " more wait their turn (at most " +
         std::to_string(static_cast<int>(limits.max_wait_seconds)) + " s); beyond\n"
         "that, and while a method is precomputed, HTTP 503 with Retry-After.\n"
         "See doc/viewer.md.\n";
}

int run_view_command(const std::vector<std::string>& args) {
  const View_arguments a = parse_view_arguments(args);
  if (a.help) {
    std::cout << view_help();
    return 0;
  }
  const auto fail = [](const std::string& message) {
    std::fflush(stdout);
    std::cerr << "expmap: error: " << message << "\n";
    return 1;
  };

  // The page's files, read once at start: requests are answered from
  // memory by exact path, so none can reach another file (no "..", no links).
  std::map<std::string, std::shared_ptr<const Body>> page;
  try {
    page = read_page(page_folder());
  } catch (const std::exception& e) {
    return fail(e.what());
  }

  if (!std::ifstream(a.mesh)) return fail("cannot open mesh file '" + a.mesh + "' (missing or not readable)");
  Mesh mesh;
  const expmap::IO::Mesh_reading_report report = expmap::IO::read_triangle_mesh(a.mesh, mesh);
  for (const std::string& note : report.notes) std::cerr << "expmap: note: '" << a.mesh << "': " << note << "\n";
  if (!CGAL::is_triangle_mesh(mesh) || mesh.number_of_faces() == 0)
    return fail("'" + a.mesh + "' has no triangle faces to show");

  // The mesh's JSON is made while the point locator builds its trees: both
  // only read the mesh, and each takes seconds on millions of faces.
  std::future<Body> mesh_json_body =
      std::async(std::launch::async, [&mesh] { return make_body(mesh_json(mesh), "application/json"); });
  const Cache_limits cache_limits;
  Map_service service(mesh, cache_limits, a.mesh);
  const auto mesh_body = std::make_shared<const Body>(mesh_json_body.get());

  httplib::Server server;
  // A thread for each query that may run or wait on each method, and eight
  // for the page's files, status polls and requests refused at once: a
  // connection holds its thread while it is kept alive.
  const std::size_t threads =
      viewer_methods().size() * (cache_limits.queries_per_method + cache_limits.waiting_per_method) + 8;
  server.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  server.set_payload_max_length(4096);  // only GET requests are served
  server.set_read_timeout(10);
  server.set_keep_alive_max_count(1000);

  int port = a.port;
  // A page elsewhere could reach a loopback server through a DNS name that
  // resolves to 127.0.0.1; answering only requests addressed to this
  // machine's own names keeps such pages out.
  const bool loopback = is_loopback(a.host);
  // The bound address itself is one of them (e.g. 127.0.0.2 given to --host).
  const std::string bound = url_host(a.host);
  server.set_pre_routing_handler([&](const httplib::Request& req, httplib::Response& res) {
    if (!loopback) return httplib::Server::HandlerResponse::Unhandled;
    const std::string host = req.get_header_value("Host");
    const std::string p = ":" + std::to_string(port);
    for (const std::string& name : {std::string("127.0.0.1"), std::string("localhost"),
                                    std::string("[::1]"), bound})
      if (host == name + p) return httplib::Server::HandlerResponse::Unhandled;
    const std::string also = bound == "127.0.0.1" || bound == "localhost" ? "" : bound + p + ", ";
    send_json(res, 403, error_json("this server answers only requests to " + also + "127.0.0.1" + p +
                                   " or localhost" + p));
    return httplib::Server::HandlerResponse::Handled;
  });

  server.Get("/api/mesh", [&](const httplib::Request& req, httplib::Response& res) {
    send(res, 200, mesh_body, req);
  });
  server.Get("/api/status", [&](const httplib::Request&, httplib::Response& res) {
    answer(res, [&] { return std::make_pair(status_json(service), false); });
  });
  server.Get("/api/map", [&](const httplib::Request& req, httplib::Response& res) {
    answer(res, [&] {
      const Map_response r = service.compute(req.params);
      return std::make_pair(map_json(r), leaves_much_free(r));
    });
  });
  server.Get(R"(/.*)", [&](const httplib::Request& req, httplib::Response& res) {
    const auto it = page.find(req.path == "/" ? std::string("/index.html") : req.path);
    if (it == page.end() && req.path.rfind("/api/", 0) == 0) {
      send_json(res, 404, error_json("no such API: " + shown(req.path)));
      return;
    }
    if (it == page.end()) {
      res.status = 404;
      res.set_content("not found\n", "text/plain; charset=utf-8");
      return;
    }
    send(res, 200, it->second, req);
  });
  // What the library refuses before any handler (a request too long, a
  // method other than GET): a message in the API's form.
  server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (res.has_header("Content-Type")) return;  // the handler's own message
    if (req.path.rfind("/api/", 0) == 0)
      send_json(res, res.status, error_json("the request was refused (HTTP " + std::to_string(res.status) + ")"));
  });

  if (port == 0) {
    port = server.bind_to_any_port(a.host);
    if (port < 0) return fail("cannot listen on " + a.host + " (is it an address of this machine?)");
  } else if (!server.bind_to_port(a.host, port)) {
    return fail("cannot listen on " + a.host + ":" + std::to_string(port) +
                " (in use? choose another with --port, or --port 0 for any free one)");
  }
  std::printf("mesh:        %s: %zu vertices, %zu faces\n", a.mesh.c_str(),
              static_cast<std::size_t>(mesh.number_of_vertices()),
              static_cast<std::size_t>(mesh.number_of_faces()));
  std::printf("viewer:      http://%s:%d/\n", bound.c_str(), port);
  std::fflush(stdout);
  if (!server.listen_after_bind()) return fail("the server stopped unexpectedly");
  return 0;
}

}  // namespace expmap_view
