"use strict";
// The ladder's pages over its JSON API. Tokens stay in this tab (sessionStorage) and go only in the
// Authorization header, never in a cookie: another site's page cannot act for a signed-in user.
const page = document.body.dataset.page;
const esc = s => String(s ?? "").replace(/[&<>"']/g, c => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
const token = kind => sessionStorage.getItem(kind + "-token");
async function api(path, options = {}, kind = "team") {
  const headers = Object.assign({}, options.headers || {});
  const t = token(kind);
  if (t) headers.Authorization = "Bearer " + t;
  const response = await fetch(path, Object.assign({}, options, { headers }));
  const body = await response.json().catch(() => ({}));
  if (!response.ok && response.status !== 422) throw new Error(body.error || response.statusText);
  return body;
}
// The ladder this page is about (?ladder=ID), kept in the links between pages; none: the service's only ladder.
const chosen = new URLSearchParams(location.search).get("ladder");
const lq = path => chosen ? path + (path.includes("?") ? "&" : "?") + "ladder=" + encodeURIComponent(chosen) : path;
for (const a of document.querySelectorAll("nav a")) if (a.getAttribute("href") !== "/ladders") a.href = lq(a.getAttribute("href"));
const ladderList = () => api("/api/ladders");
// Several ladders and none chosen: the overview lets the reader choose (true when it went there).
async function toOverview() {
  if (chosen || (await ladderList()).ladders.length < 2) return false;
  location.replace("/ladders");
  return true;
}
const teamLink = n => `<a href="/teams/${encodeURIComponent(n)}">${esc(n)}</a>`;
const matchLink = id => `<a href="/matches/${id}">${id}</a>`;
const score = m => m.score ? m.score.join(":") : m.forfeits ? "forfeit" : "";
const subs = m => (m.submissions || []).map(s => s === null ? "house" : "#" + s).join(" vs ");

async function standings() {
  if (await toOverview()) return;
  const s = await api(lq("/api/standings"));
  document.getElementById("item").textContent = s.item;
  document.getElementById("summary").textContent = s.final
    ? `final round: top ${s.finalRound.top}, each pair ${s.finalRound.rounds} times; ${s.finalRound.played} of ${s.finalRound.matches} matches played (ranked play has stopped)`
    : s.matches + " matches played";
  document.querySelector("#standings tbody").innerHTML = s.entrants.map(e =>
    `<tr><td class="num">${e.rank}</td><td>${teamLink(e.name)}</td><td class="num">${e.rating}</td><td>${e.ci[0]} to ${e.ci[1]}</td>` +
    `<td class="num">${e.played}</td><td class="num">${e.wins}</td><td class="num">${e.draws}</td><td class="num">${e.losses}</td></tr>`).join("");
}

async function team() {
  const name = decodeURIComponent(location.pathname.split("/")[2]);
  const t = await api("/api/teams/" + encodeURIComponent(name));
  document.getElementById("name").textContent = t.name;
  document.getElementById("who").textContent = t.house ? "house entrant: " + t.house : t.signedIn ? "signed in: you see your compile logs and your strategy's logs" : "";
  document.getElementById("upload").hidden = !t.signedIn;
  const l = await ladderList();
  const item = id => { const x = l.ladders.find(y => y.id === id); return x ? `${x.item} (${x.id})` : String(id); };
  const choice = document.querySelector("#submit select[name=ladder]");
  if (choice.options.length !== l.ladders.length) {
    choice.innerHTML = l.ladders.map(x => `<option value="${x.id}">${esc(item(x.id))}</option>`).join("");
    if (chosen) choice.value = chosen;
  }
  document.getElementById("submit-ladder").hidden = l.ladders.length < 2;
  document.querySelector("#submissions tbody").innerHTML = t.submissions.map(s =>
    `<tr><td class="num">${s.id}</td><td>${esc(item(s.ladder))}</td><td>${esc(s.created)}</td><td>${esc(s.state)}</td><td><pre>${esc(s.log ?? "")}</pre></td></tr>`).join("");
  document.getElementById("faults").textContent = t.faults
    ? `faults: ${t.faults.counts}; first in match ${t.faults.first.match}${t.faults.first.cycle ? ", cycle " + t.faults.first.cycle : ""}: ${t.faults.first.text}` : "no faults";
  const ids = chosen ? [chosen] : l.ladders.map(x => x.id);
  const m = { matches: (await Promise.all(ids.map(id => api(`/api/matches?team=${encodeURIComponent(name)}&limit=100&ladder=${encodeURIComponent(id)}`))))
    .flatMap(x => x.matches).sort((a, b) => b.id - a.id).slice(0, 100) };
  const side = x => x.teams.indexOf(t.name);
  const faults = x => { const f = (x.sideFaults || [])[side(x)]; return f ? [[f.exceptions, "exceptions"], [f.timeouts, "timeouts"], [f.badAnswers, "bad answers"], [f.hostEnds, "host ends"]].filter(p => p[0]).map(p => p.join(" ")).join(", ") : ""; };
  const slowest = x => { const ms = (x.slowestMs || [])[side(x)]; return ms === undefined || ms === null ? "" : ms + " ms"; };
  const log = x => t.signedIn && x.state === "done" ? `<button class="log" data-match="${x.id}">log</button>` : "";
  document.querySelector("#matches tbody").innerHTML = m.matches.map(x =>
    `<tr><td class="num">${matchLink(x.id)}</td><td>${esc(x.state)}</td><td>${x.teams.map(teamLink).join(" vs ")}</td><td>${score(x)}</td><td>${subs(x)}</td>` +
    `<td>${esc(faults(x))}</td><td class="num">${esc(slowest(x))}</td><td>${log(x)}</td></tr>`).join("");
  for (const b of document.querySelectorAll("#matches button.log")) {
    b.addEventListener("click", async () => {
      try { const l = await api(`/api/teams/${encodeURIComponent(t.name)}/matches/${b.dataset.match}/log`); show("strategy-log", `match ${l.match}:\n${l.log || "(nothing printed)"}`); }
      catch (e) { show("strategy-log", e.message, true); }
    });
  }
}

async function match() {
  const id = location.pathname.split("/")[2];
  const m = await api("/api/matches/" + encodeURIComponent(id));
  document.getElementById("title").textContent = `Match ${m.id}: ${m.teams.join(" vs ")}`;
  document.getElementById("details").innerHTML = `${esc(m.state)} · ladder ${m.ladder} · seed ${esc(m.seed)} · submissions ${subs(m)}` +
    (m.score ? ` · score ${score(m)}` : "") + (m.reasons ? ` · <span class="error">${m.reasons.map(esc).join("; ")}</span>` : "");
  const frame = document.getElementById("replay");
  if (m.replay && frame.hidden) { frame.src = m.replay; frame.hidden = false; }
}

async function queue() {
  if (await toOverview()) return;
  const w = await api(lq("/api/matches?state=running,queued&limit=200"));
  document.querySelector("#waiting tbody").innerHTML = w.matches.map(x =>
    `<tr><td class="num">${matchLink(x.id)}</td><td>${esc(x.state)}</td><td>${x.teams.map(teamLink).join(" vs ")}</td><td>${subs(x)}</td><td>${esc(x.created)}</td></tr>`).join("");
  const d = await api(lq("/api/matches?state=done&limit=50"));
  document.querySelector("#done tbody").innerHTML = d.matches.map(x =>
    `<tr><td class="num">${matchLink(x.id)}</td><td>${x.teams.map(teamLink).join(" vs ")}</td><td>${score(x)}</td><td>${subs(x)}</td><td>${esc(x.finished)}</td></tr>`).join("");
}

async function ladders() {
  const l = await ladderList();
  const state = x => x.final ? "final round" : x.paused ? "paused" : "playing";
  document.querySelector("#ladders tbody").innerHTML = l.ladders.map(x =>
    `<tr><td class="num"><a href="/?ladder=${x.id}">${x.id}</a></td><td><a href="/?ladder=${x.id}">${esc(x.item)}</a></td><td class="num">${x.cycles}</td><td>${state(x)}</td>` +
    `<td class="num">${x.teams}</td><td class="num">${x.matches}</td><td>${x.leader ? teamLink(x.leader) : ""}</td><td><a href="/queue?ladder=${x.id}">queue</a></td></tr>`).join("");
}

async function organiser() {
  const all = await ladderList();
  const choice = document.getElementById("ladder-choice");
  choice.innerHTML = (chosen || all.ladders.length === 1 ? "" : `<option value="">choose a ladder</option>`) +
    all.ladders.map(x => `<option value="${x.id}">${x.id}: ${esc(x.item)}</option>`).join("");
  if (chosen) choice.value = chosen;
  const items = document.querySelector("#create-ladder select[name=item]");
  if (items.options.length === 0) items.innerHTML = all.items.map(i => `<option>${esc(i)}</option>`).join("");
  document.getElementById("export-results").href = lq("/api/export/results.jsonl");
  document.getElementById("export-standings").href = lq("/api/export/standings.json");
  document.getElementById("admin").hidden = !token("admin");
  if (!chosen && all.ladders.length > 1) { document.getElementById("ladder").textContent = `this service runs ${all.ladders.length} ladders: choose one`; return; }
  const l = await api(lq("/api/ladder"));
  document.getElementById("ladder").textContent = `${l.item}, ${l.cycles} cycles a match, ${l.paused ? "paused" : "playing"}, ${l.submissionsPerDay} submissions a day`;
  document.getElementById("final-state").textContent = l.final
    ? `final round started: ${l.final.teams.join(", ")}, each pair ${l.final.rounds} times; ${l.final.played} of ${l.final.matches} played` : "";
}

function form(id, handler) {
  const f = document.getElementById(id);
  if (f) f.addEventListener("submit", e => { e.preventDefault(); handler(new FormData(f)); });
}
const show = (id, text, bad) => { const p = document.getElementById(id); p.textContent = text; p.className = bad ? "error" : ""; };
const post = (path, body, kind) => api(path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body || {}) }, kind);

form("signin", async d => {
  sessionStorage.setItem("team-token", d.get("token"));
  try { const me = await api("/api/me"); location.href = "/teams/" + encodeURIComponent(me.name); }
  catch (e) { sessionStorage.removeItem("team-token"); show("signin-result", e.message, true); }
});
form("signin-password", async d => {
  try { const s = await post("/api/signin", { name: d.get("name"), password: d.get("password") }); sessionStorage.setItem("team-token", s.token); location.href = "/teams/" + encodeURIComponent(s.name); }
  catch (e) { show("signin-result", e.message, true); }
});
form("submit", async d => {
  const body = new FormData();
  for (const f of document.querySelector("#submit input[type=file]").files) body.append("file", f, f.name);
  const ladder = d.get("ladder");
  try { const s = await api("/api/submissions" + (ladder ? "?ladder=" + encodeURIComponent(ladder) : ""), { method: "POST", body }); show("submit-log", `submission ${s.id}: ${s.state}\n${s.log}`, s.state !== "ok"); refresh(); }
  catch (e) { show("submit-log", e.message, true); }
});
form("admin-signin", async d => {
  sessionStorage.setItem("admin-token", d.get("token"));
  try { const me = await api("/api/me", {}, "admin"); if (me.role !== "organiser") throw new Error("not the organiser's token"); refresh(); }
  catch (e) { sessionStorage.removeItem("admin-token"); show("admin-result", e.message, true); document.getElementById("admin").hidden = true; }
});
form("add-team", async d => {
  try { const t = await post(d.get("strategy") ? lq("/api/teams") : "/api/teams", { name: d.get("name"), strategy: d.get("strategy") || null }, "admin"); show("team-token", `team ${t.name} added; its token (shown once): ${t.token}`); }
  catch (e) { show("team-token", e.message, true); }
});
form("requeue", async d => { try { await post(`/api/matches/${encodeURIComponent(d.get("id"))}/requeue`, {}, "admin"); show("admin-result", "requeued"); } catch (e) { show("admin-result", e.message, true); } });
form("final", async d => {
  try { const f = await post(lq("/api/final"), { top: Number(d.get("top")), rounds: Number(d.get("rounds")) }, "admin"); show("admin-result", `final round started: ${f.final.matches} matches`); refresh(); }
  catch (e) { show("admin-result", e.message, true); }
});
form("limit", async d => { try { await post("/api/settings", { submissionsPerDay: Number(d.get("n")) }, "admin"); show("admin-result", "set"); refresh(); } catch (e) { show("admin-result", e.message, true); } });
form("create-ladder", async d => {
  try {
    const l = await post("/api/ladders", { item: d.get("item"), minutes: Number(d.get("minutes")), firstSeed: Number(d.get("firstSeed")) }, "admin");
    show("ladder-result", `ladder ${l.id} created: ${l.item}, ${l.cycles} cycles a match, first seed ${l.firstSeed}`); refresh();
  } catch (e) { show("ladder-result", e.message, true); }
});
const choice = document.getElementById("ladder-choice");
if (choice) choice.addEventListener("change", () => { if (choice.value) location.search = "?ladder=" + encodeURIComponent(choice.value); });
for (const [id, path] of [["pause", "/api/ladder/pause"], ["resume", "/api/ladder/resume"]]) {
  const b = document.getElementById(id);
  if (b) b.addEventListener("click", async () => { try { await post(lq(path), {}, "admin"); refresh(); } catch (e) { show("admin-result", e.message, true); } });
}

const pages = { ladders, standings, team, match, queue, organiser };
async function refresh() { try { await pages[page](); } catch (e) { console.error(e); } }
refresh();
if (page !== "organiser") setInterval(refresh, 2000);
