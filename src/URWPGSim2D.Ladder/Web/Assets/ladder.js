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
const teamLink = n => `<a href="/teams/${encodeURIComponent(n)}">${esc(n)}</a>`;
const matchLink = id => `<a href="/matches/${id}">${id}</a>`;
const score = m => m.score ? m.score.join(":") : m.forfeits ? "forfeit" : "";
const subs = m => (m.submissions || []).map(s => s === null ? "house" : "#" + s).join(" vs ");

async function standings() {
  const s = await api("/api/standings");
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
  document.querySelector("#submissions tbody").innerHTML = t.submissions.map(s =>
    `<tr><td class="num">${s.id}</td><td>${esc(s.created)}</td><td>${esc(s.state)}</td><td><pre>${esc(s.log ?? "")}</pre></td></tr>`).join("");
  document.getElementById("faults").textContent = t.faults
    ? `faults: ${t.faults.counts}; first in match ${t.faults.first.match}${t.faults.first.cycle ? ", cycle " + t.faults.first.cycle : ""}: ${t.faults.first.text}` : "no faults";
  const m = await api("/api/matches?team=" + encodeURIComponent(name) + "&limit=100");
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
  document.getElementById("details").innerHTML = `${esc(m.state)} · seed ${esc(m.seed)} · submissions ${subs(m)}` +
    (m.score ? ` · score ${score(m)}` : "") + (m.reasons ? ` · <span class="error">${m.reasons.map(esc).join("; ")}</span>` : "");
  const frame = document.getElementById("replay");
  if (m.replay && frame.hidden) { frame.src = m.replay; frame.hidden = false; }
}

async function queue() {
  const w = await api("/api/matches?state=running,queued&limit=200");
  document.querySelector("#waiting tbody").innerHTML = w.matches.map(x =>
    `<tr><td class="num">${matchLink(x.id)}</td><td>${esc(x.state)}</td><td>${x.teams.map(teamLink).join(" vs ")}</td><td>${subs(x)}</td><td>${esc(x.created)}</td></tr>`).join("");
  const d = await api("/api/matches?state=done&limit=50");
  document.querySelector("#done tbody").innerHTML = d.matches.map(x =>
    `<tr><td class="num">${matchLink(x.id)}</td><td>${x.teams.map(teamLink).join(" vs ")}</td><td>${score(x)}</td><td>${subs(x)}</td><td>${esc(x.finished)}</td></tr>`).join("");
}

async function organiser() {
  const l = await api("/api/ladder");
  document.getElementById("ladder").textContent = `${l.item}, ${l.cycles} cycles a match, ${l.paused ? "paused" : "playing"}, ${l.submissionsPerDay} submissions a day`;
  document.getElementById("admin").hidden = !token("admin");
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
  try { const s = await api("/api/submissions", { method: "POST", body }); show("submit-log", `submission ${s.id}: ${s.state}\n${s.log}`, s.state !== "ok"); refresh(); }
  catch (e) { show("submit-log", e.message, true); }
});
form("admin-signin", async d => {
  sessionStorage.setItem("admin-token", d.get("token"));
  try { const me = await api("/api/me", {}, "admin"); if (me.role !== "organiser") throw new Error("not the organiser's token"); refresh(); }
  catch (e) { sessionStorage.removeItem("admin-token"); show("admin-result", e.message, true); document.getElementById("admin").hidden = true; }
});
form("add-team", async d => {
  try { const t = await post("/api/teams", { name: d.get("name"), strategy: d.get("strategy") || null }, "admin"); show("team-token", `team ${t.name} added; its token (shown once): ${t.token}`); }
  catch (e) { show("team-token", e.message, true); }
});
form("requeue", async d => { try { await post(`/api/matches/${encodeURIComponent(d.get("id"))}/requeue`, {}, "admin"); show("admin-result", "requeued"); } catch (e) { show("admin-result", e.message, true); } });
form("final", async d => {
  try { const f = await post("/api/final", { top: Number(d.get("top")), rounds: Number(d.get("rounds")) }, "admin"); show("admin-result", `final round started: ${f.final.matches} matches`); refresh(); }
  catch (e) { show("admin-result", e.message, true); }
});
form("limit", async d => { try { await post("/api/settings", { submissionsPerDay: Number(d.get("n")) }, "admin"); show("admin-result", "set"); refresh(); } catch (e) { show("admin-result", e.message, true); } });
for (const [id, path] of [["pause", "/api/ladder/pause"], ["resume", "/api/ladder/resume"]]) {
  const b = document.getElementById(id);
  if (b) b.addEventListener("click", async () => { try { await post(path, {}, "admin"); refresh(); } catch (e) { show("admin-result", e.message, true); } });
}

const pages = { standings, team, match, queue, organiser };
async function refresh() { try { await pages[page](); } catch (e) { console.error(e); } }
refresh();
if (page !== "organiser") setInterval(refresh, 2000);
