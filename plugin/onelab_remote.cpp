#include "plugin/onelab_remote.h"

#include <map>
#include <vector>

#include "core/util/error.h"

// gmsh-doc's client, with its namespaces renamed (see the header).
#define onelab cvtmesh_onelab
#define GmshSocket CvtmeshGmshSocket
#define GmshClient CvtmeshGmshClient
#define GmshServer CvtmeshGmshServer
#include "onelab.h"
#undef onelab
#undef GmshSocket
#undef GmshClient
#undef GmshServer

namespace cvtmesh::plugin {

struct RemoteOnelab::Impl {
  std::unique_ptr<cvtmesh_onelab::remoteNetworkClient> client;
};

RemoteOnelab::RemoteOnelab(std::string name, std::unique_ptr<Impl> impl)
    : name_(std::move(name)), impl_(std::move(impl)) {}

RemoteOnelab::~RemoteOnelab() = default;

std::unique_ptr<RemoteOnelab> RemoteOnelab::connect(int argc, char** argv) {
  for (int i = 1; i + 2 < argc; ++i) {
    if (std::string(argv[i]) != "-onelab") continue;
    auto impl = std::make_unique<Impl>();
    impl->client = std::make_unique<cvtmesh_onelab::remoteNetworkClient>(argv[i + 1], argv[i + 2]);
    if (!impl->client->getGmshClient())
      throw InputError(std::string("cannot connect to Gmsh on socket '") + argv[i + 2] + "'");
    return std::unique_ptr<RemoteOnelab>(new RemoteOnelab(argv[i + 1], std::move(impl)));
  }
  return nullptr;
}

std::string RemoteOnelab::action() {
  return string(name_ + "/Action").value_or("");
}

void RemoteOnelab::set(const OnelabParam& p) {
  auto common = [&](cvtmesh_onelab::parameter& q) {
    q.setHelp(p.help);
    q.setReadOnly(p.read_only);
    q.setVisible(p.visible);
    if (p.never_changed) q.setNeverChanged(true);
    for (const auto& [k, v] : p.attributes) q.setAttribute(k, v);
  };
  if (p.is_string) {
    cvtmesh_onelab::string q(p.name, p.text);
    common(q);
    if (!p.labels.empty()) q.setChoices(p.labels);
    impl_->client->set(q);
  } else {
    cvtmesh_onelab::number q(p.name, p.number);
    common(q);
    if (p.max > p.min) {
      q.setMin(p.min);
      q.setMax(p.max);
      q.setStep(p.step);
    }
    if (!p.choices.empty()) q.setChoices(p.choices);
    if (!p.labels.empty()) {
      std::map<double, std::string> labels;
      for (std::size_t i = 0; i < p.labels.size() && i < p.choices.size(); ++i)
        labels[p.choices[i]] = p.labels[i];
      q.setValueLabels(labels);
    }
    impl_->client->set(q);
  }
}

std::optional<double> RemoteOnelab::number(const std::string& name) {
  std::vector<cvtmesh_onelab::number> v;
  impl_->client->get(v, name);
  if (v.empty()) return std::nullopt;
  return v[0].getValue();
}

std::optional<std::string> RemoteOnelab::string(const std::string& name) {
  std::vector<cvtmesh_onelab::string> v;
  impl_->client->get(v, name);
  if (v.empty()) return std::nullopt;
  return v[0].getValue();
}

void RemoteOnelab::info(const std::string& message) {
  impl_->client->sendInfo(message);
}
void RemoteOnelab::error(const std::string& message) {
  impl_->client->sendError(message);
}
void RemoteOnelab::progress(const std::string& message) {
  impl_->client->sendProgress(message);
}
void RemoteOnelab::parse_string(const std::string& text) {
  impl_->client->sendParseStringRequest(text);
}

}  // namespace cvtmesh::plugin
