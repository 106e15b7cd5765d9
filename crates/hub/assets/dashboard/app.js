var jh="fleetlink.token",Qh="fleetlink.principal",ys={token(){return sessionStorage.getItem(jh)},principal(){return sessionStorage.getItem(Qh)},set(n,e){sessionStorage.setItem(jh,n),sessionStorage.setItem(Qh,e)},clear(){sessionStorage.removeItem(jh),sessionStorage.removeItem(Qh)},wsUrl(){let n=location.protocol==="https:"?"wss:":"ws:",e=this.token();return`${n}//${location.host}/${e?`?token=${encodeURIComponent(e)}`:""}`}};var $o=class extends Error{constructor(t,i){super(i);this.status=t}status};async function Ti(n,e={}){let t=new Headers(e.headers),i=ys.token();i&&t.set("Authorization",`Bearer ${i}`),e.body&&t.set("Content-Type","application/json");let s=await fetch(n,{...e,headers:t,cache:"no-store"}),r=await s.text(),o=null;try{o=r?JSON.parse(r):null}catch{o=r}if(!s.ok)throw new $o(s.status,o&&o.error||r||`HTTP ${s.status}`);return o}var Ot={frames:{},poses:{},feedback:[],lastResult:null,lastServiceResponse:null,disabled:{},renders:0,cloudAgesMs:[],busyMs:{decode:0,cloudUnpack:0,cloudRender:0},mapToScreen:null};function ci(n){Ot.frames[n]=(Ot.frames[n]??0)+1}globalThis.fleetlink=Ot;var tu;try{tu=new TextDecoder}catch{}var ze,hn,ie=0;var tp=[],cu=105,u_=57342,f_=57343,Jd=57337;var Kd=6,tl=11281e4,Xr=1681e4,d_=1671e4,qr=d_,nu=tp,iu=0,Ct={},un,rl,ol=0,jo=0,wn,Ai,fn=[],su=[],Vn,Jn,ns,jd={useRecords:!1,mapsAsObjects:!0},Qo=!1,np=2;try{new Function("")}catch{np=1/0}var vs=class n{constructor(e){if(e&&((e.keyMap||e._keyMap)&&!e.useRecords&&(e.useRecords=!1,e.mapsAsObjects=!0),e.useRecords===!1&&e.mapsAsObjects===void 0&&(e.mapsAsObjects=!0),e.getStructures&&(e.getShared=e.getStructures),e.getShared&&!e.structures&&((e.structures=[]).uninitialized=!0),e.keyMap)){this.mapKey=new Map;for(let[t,i]of Object.entries(e.keyMap))this.mapKey.set(i,t)}Object.assign(this,e)}decodeKey(e){return this.keyMap&&this.mapKey.get(e)||e}encodeKey(e){return this.keyMap&&this.keyMap.hasOwnProperty(e)?this.keyMap[e]:e}encodeKeys(e){if(!this._keyMap)return e;let t=new Map;for(let[i,s]of Object.entries(e))t.set(this._keyMap.hasOwnProperty(i)?this._keyMap[i]:i,s);return t}decodeKeys(e){if(!this._keyMap||e.constructor.name!="Map")return e;if(!this._mapKey){this._mapKey=new Map;for(let[i,s]of Object.entries(this._keyMap))this._mapKey.set(s,i)}let t={};return e.forEach((i,s)=>t[Ri(this._mapKey.has(s)?this._mapKey.get(s):s)]=i),t}mapDecode(e,t){let i=this.decode(e);return this._keyMap&&i.constructor.name==="Array"?i.map(s=>this.decodeKeys(s)):i}decode(e,t){if(ze)return lu(()=>(Ko(),this?this.decode(e,t):n.prototype.decode.call(jd,e,t)));hn=t>-1&&t<e.length?t:e.length,ie=0,iu=0,jo=0,rl=null,nu=tp,wn=null,ze=e;try{Jn=e.dataView||(e.dataView=new DataView(e.buffer,e.byteOffset,e.byteLength))}catch(i){throw ze=null,e instanceof Uint8Array?i:new Error("Source must be a Uint8Array or Buffer but was a "+(e&&typeof e=="object"?e.constructor.name:typeof e))}if(this instanceof n){if(Ct=this,Vn=this.sharedValues&&(this.pack?new Array(this.maxPrivatePackedValues||16).concat(this.sharedValues):this.sharedValues),this.structures)return un=this.structures,nl();(!un||un.length>0)&&(un=[])}else Ct=jd,(!un||un.length>0)&&(un=[]),Vn=null;return nl()}decodeMultiple(e,t){if(ze)return lu(()=>(Ko(),this?this.decodeMultiple(e,t):ll.decodeMultiple(e,t)));let i,s=0;try{let r=e.length;Qo=!0;let o=this?this.decode(e,r):ll.decode(e,r);if(t){let a=ie;if(t(o)===!1)return;for(;a<r;)if(s=a,o=nl(),a=ie,t(o)===!1)return}else{for(i=[o];ie<r;)s=ie,i.push(nl());return i}}catch(r){throw r&&(typeof r=="object"||typeof r=="function")&&(r.lastPosition=s,r.values=i),r}finally{Qo=!1,Ko()}}};var ip=new WeakSet,al;function nl(){try{al=hn-ie;let n=Rt();if(wn){if(ie>=wn.postBundlePosition)throw new Error("Unexpected bundle position");ie=wn.postBundlePosition,wn=null}if(ie==hn)un=null,ze=null,Ai&&(Ai=null);else if(ie>hn){let e=new Error("Unexpected end of CBOR data");throw e.incomplete=!0,e}else if(!Qo)throw new Error("Data read, but end of buffer not reached");return n}catch(n){throw Ko(),ip.has(n)?n.incomplete&&(n.incomplete=!1):(n instanceof RangeError&&ie+8>hn||n&&typeof n.message=="string"&&n.message.startsWith("Unexpected end of buffer"))&&(n.incomplete=!0),n}}function Zo(){return ie<hn&&ze[ie]===255?(ie++,!0):!1}function hi(n){let e=new Error("Unexpected end of CBOR data");return e.incomplete=!0,n&&(e.neededEnd=n),e}function Rt(){if(!(ie<hn))throw hi();let n=ze[ie++],e=n>>5;if(n=n&31,n>23)switch(n){case 24:if(ie>=hn)throw hi();n=ze[ie++];break;case 25:if(e==7)return g_();n=Jn.getUint16(ie),ie+=2;break;case 26:if(e==7){let t=Jn.getFloat32(ie);if(Ct.useFloat32>2){let i=cl[(ze[ie]&127)<<1|ze[ie+1]>>7];return ie+=4,(i*t+(t>0?.5:-.5)>>0)/i}return ie+=4,t}if(n=Jn.getUint32(ie),ie+=4,e===1)return-1-n;break;case 27:if(e==7){let t=Jn.getFloat64(ie);return ie+=8,t}if(e>1){if(Jn.getUint32(ie)>0)throw new Error("JavaScript does not support arrays, maps, or strings with length over 4294967295");n=Jn.getUint32(ie+4)}else if(Ct.int64AsNumber){if(n=Jn.getUint32(ie)*4294967296,n+=Jn.getUint32(ie+4),ie+=8,e===1)return-1-n;break}else n=Jn.getBigUint64(ie);ie+=8;break;case 31:switch(e){case 2:case 3:throw new Error("Indefinite length not supported for byte or text strings");case 4:let t=[],i=0;for(;!Zo();){if(i>=tl)throw new Error(`Array length exceeds ${tl}`);t[i++]=Rt()}return e==4?t:e==3?t.join(""):Buffer.concat(t);case 5:let s;if(Ct.mapsAsObjects){let r={},o=0;if(Ct.keyMap)for(;!Zo();){if(s=Rt(),o++>=qr)throw new Error(`Property count exceeds ${qr}`);r[Ri(Ct.decodeKey(s))]=Rt()}else for(;!Zo();){if(s=Rt(),o++>=qr)throw new Error(`Property count exceeds ${qr}`);r[Ri(s)]=Rt()}return r}else{ns&&(Ct.mapsAsObjects=!0,ns=!1);let r=new Map;if(Ct.keyMap){let o=0;for(;!Zo();){if(s=Rt(),o++>=Xr)throw new Error(`Map size exceeds ${Xr}`);r.set(Ct.decodeKey(s),Rt())}}else{let o=0;for(;!Zo();){if(s=Rt(),o++>=Xr)throw new Error(`Map size exceeds ${Xr}`);r.set(s,Rt())}}return r}case 7:throw new Error("Unexpected break stop code outside of an indefinite-length item");default:throw new Error("Invalid major type for indefinite length "+e)}default:throw new Error("Unknown token "+n)}switch(e){case 0:return n;case 1:return~n;case 2:if(n>hn-ie)throw hi(ie+n);return m_(n);case 3:if(jo>=ie)return rl.slice(ie-ol,(ie+=n)-ol);if(n>hn-ie)throw hi(ie+n);if(jo==0&&hn<140&&n<32){let s=n<16?sp(n):p_(n);if(s!=null)return s}return sl(n);case 4:if(n>tl)throw new Error(`Array length exceeds ${tl}`);if(n>hn-ie||(al-=n)<0)throw hi(ie+n);let t=new Array(n);for(let s=0;s<n;s++)t[s]=Rt();return t;case 5:if(Ct.mapsAsObjects){if(n>qr)throw new Error(`Property count exceeds ${qr}`);if(n>(hn-ie)/2)throw hi(ie+2*n);let s={};if(Ct.keyMap)for(let r=0;r<n;r++)s[Ri(Ct.decodeKey(Rt()))]=Rt();else for(let r=0;r<n;r++)s[Ri(Rt())]=Rt();return s}else{if(ns&&(Ct.mapsAsObjects=!0,ns=!1),n>Xr)throw new Error(`Map size exceeds ${Xr}`);if(n>(hn-ie)/2)throw hi(ie+2*n);let s=new Map;if(Ct.keyMap)for(let r=0;r<n;r++)s.set(Ct.decodeKey(Rt()),Rt());else for(let r=0;r<n;r++)s.set(Rt(),Rt());return s}case 6:if(n>=Jd){let s=un[n&8191];if(s)return s.read||(s.read=ru(s)),s.read();if(n<65536){if(n==f_){let r=$r(),o=Rt(),a=Rt();au(o,a);let c={};if(Ct.keyMap)for(let l=2;l<r;l++){let h=Ct.decodeKey(a[l-2]);c[Ri(h)]=Rt()}else for(let l=2;l<r;l++){let h=a[l-2];c[Ri(h)]=Rt()}return c}else if(n==u_){let r=$r(),o=Rt();for(let a=2;a<r;a++)au(o++,Rt());return Rt()}else if(n==Jd)return b_();if(Ct.getShared&&(hu(),s=un[n&8191],s))return s.read||(s.read=ru(s)),s.read()}}let i=fn[n];if(i)return i.handlesRead?i(Rt):i(Rt());{let s=Rt();for(let r=0;r<su.length;r++){let o=su[r](n,s);if(o!==void 0)return o}return new Fi(s,n)}case 7:switch(n){case 20:return!1;case 21:return!0;case 22:return null;case 23:return;default:let s=(Vn||pr())[n];if(s!==void 0)return s;throw new Error("Unknown token "+n)}default:throw isNaN(n)?hi():new Error("Unknown CBOR token "+n)}}var Qd=/^[a-zA-Z_$][a-zA-Z\d_$]*$/;function ru(n){if(!n)throw new Error("Structure is required in record definition");function e(){let t=ze[ie++];if(t=t&31,t>23)switch(t){case 24:t=ze[ie++];break;case 25:t=Jn.getUint16(ie),ie+=2;break;case 26:t=Jn.getUint32(ie),ie+=4;break;default:throw new Error("Expected array header, but got "+ze[ie-1])}let i=this.compiledReader;for(;i;){if(i.propertyCount===t)return i(Rt);i=i.next}if(this.slowReads++>=np){let r=this.length==t?this:this.slice(0,t);return i=Ct.keyMap?new Function("r","return {"+r.map(o=>Ct.decodeKey(o)).map(o=>Qd.test(o)?Ri(o)+":r()":"["+JSON.stringify(o)+"]:r()").join(",")+"}"):new Function("r","return {"+r.map(o=>Qd.test(o)?Ri(o)+":r()":"["+JSON.stringify(o)+"]:r()").join(",")+"}"),this.compiledReader&&(i.next=this.compiledReader),i.propertyCount=t,this.compiledReader=i,i(Rt)}let s={};if(Ct.keyMap)for(let r=0;r<t;r++)s[Ri(Ct.decodeKey(this[r]))]=Rt();else for(let r=0;r<t;r++)s[Ri(this[r])]=Rt();return s}return n.slowReads=0,e}function Ri(n){if(typeof n=="string")return n==="__proto__"?"__proto_":n;if(typeof n=="number"||typeof n=="boolean"||typeof n=="bigint")return n.toString();if(n==null)return n+"";throw new Error("Invalid property name type "+typeof n)}var sl=ou;function ou(n){let e;if(n<16&&(e=sp(n)))return e;if(n>64&&tu)return tu.decode(ze.subarray(ie,ie+=n));let t=ie+n,i=[];for(e="";ie<t;){let s=ze[ie++];if((s&128)===0)i.push(s);else if((s&224)===192)if(s<194||ie>=t||(ze[ie]&192)!==128)i.push(65533);else{let r=ze[ie++]&63;i.push((s&31)<<6|r)}else if((s&240)===224){let r=ie<t?ze[ie]:0;if(ie>=t||(r&192)!==128||s===224&&r<160||s===237&&r>=160)i.push(65533);else if(ie++,ie>=t||(ze[ie]&192)!==128)i.push(65533);else{let o=ze[ie++]&63;i.push((s&31)<<12|(r&63)<<6|o)}}else if((s&248)===240){let r=ie<t?ze[ie]:0;if(s>244||ie>=t||(r&192)!==128||s===240&&r<144||s===244&&r>=144)i.push(65533);else if(ie++,ie>=t||(ze[ie]&192)!==128)i.push(65533);else{let o=ze[ie++]&63;if(ie>=t||(ze[ie]&192)!==128)i.push(65533);else{let a=ze[ie++]&63,c=(s&7)<<18|(r&63)<<12|o<<6|a;c-=65536,i.push(c>>>10&1023|55296),i.push(56320|c&1023)}}}else i.push(65533);i.length>=4096&&(e+=Nn.apply(String,i),i.length=0)}return i.length>0&&(e+=Nn.apply(String,i)),e}var Nn=String.fromCharCode;function p_(n){let e=ie,t=new Array(n);for(let i=0;i<n;i++){let s=ze[ie++];if((s&128)>0){ie=e;return}t[i]=s}return Nn.apply(String,t)}function sp(n){if(n<4)if(n<2){if(n===0)return"";{let e=ze[ie++];if((e&128)>1){ie-=1;return}return Nn(e)}}else{let e=ze[ie++],t=ze[ie++];if((e&128)>0||(t&128)>0){ie-=2;return}if(n<3)return Nn(e,t);let i=ze[ie++];if((i&128)>0){ie-=3;return}return Nn(e,t,i)}else{let e=ze[ie++],t=ze[ie++],i=ze[ie++],s=ze[ie++];if((e&128)>0||(t&128)>0||(i&128)>0||(s&128)>0){ie-=4;return}if(n<6){if(n===4)return Nn(e,t,i,s);{let r=ze[ie++];if((r&128)>0){ie-=5;return}return Nn(e,t,i,s,r)}}else if(n<8){let r=ze[ie++],o=ze[ie++];if((r&128)>0||(o&128)>0){ie-=6;return}if(n<7)return Nn(e,t,i,s,r,o);let a=ze[ie++];if((a&128)>0){ie-=7;return}return Nn(e,t,i,s,r,o,a)}else{let r=ze[ie++],o=ze[ie++],a=ze[ie++],c=ze[ie++];if((r&128)>0||(o&128)>0||(a&128)>0||(c&128)>0){ie-=8;return}if(n<10){if(n===8)return Nn(e,t,i,s,r,o,a,c);{let l=ze[ie++];if((l&128)>0){ie-=9;return}return Nn(e,t,i,s,r,o,a,c,l)}}else if(n<12){let l=ze[ie++],h=ze[ie++];if((l&128)>0||(h&128)>0){ie-=10;return}if(n<11)return Nn(e,t,i,s,r,o,a,c,l,h);let f=ze[ie++];if((f&128)>0){ie-=11;return}return Nn(e,t,i,s,r,o,a,c,l,h,f)}else{let l=ze[ie++],h=ze[ie++],f=ze[ie++],u=ze[ie++];if((l&128)>0||(h&128)>0||(f&128)>0||(u&128)>0){ie-=12;return}if(n<14){if(n===12)return Nn(e,t,i,s,r,o,a,c,l,h,f,u);{let p=ze[ie++];if((p&128)>0){ie-=13;return}return Nn(e,t,i,s,r,o,a,c,l,h,f,u,p)}}else{let p=ze[ie++],g=ze[ie++];if((p&128)>0||(g&128)>0){ie-=14;return}if(n<15)return Nn(e,t,i,s,r,o,a,c,l,h,f,u,p,g);let b=ze[ie++];if((b&128)>0){ie-=15;return}return Nn(e,t,i,s,r,o,a,c,l,h,f,u,p,g,b)}}}}}function m_(n){return Ct.copyBuffers?Uint8Array.prototype.slice.call(ze,ie,ie+=n):ze.subarray(ie,ie+=n)}var rp=new Float32Array(1),il=new Uint8Array(rp.buffer,0,4);function g_(){let n=ze[ie++],e=ze[ie++],t=(n&127)>>2;if(t===31)return e||n&3?NaN:n&128?-1/0:1/0;if(t===0){let i=((n&3)<<8|e)/16777216;return n&128?-i:i}return il[3]=n&128|(t>>1)+56,il[2]=(n&7)<<5|e>>3,il[1]=e<<5,il[0]=0,rp[0]}var kE=new Array(4096);var Fi=class{constructor(e,t){this.value=e,this.tag=t}};fn[0]=n=>new Date(n);fn[1]=n=>new Date(Math.round(n*1e3));fn[2]=n=>{let e=BigInt(0);for(let t=0,i=n.byteLength;t<i;t++)e=BigInt(n[t])+(e<<BigInt(8));return e};fn[3]=n=>BigInt(-1)-fn[2](n);fn[4]=n=>+(n[1]+"e"+n[0]);fn[5]=n=>n[1]*Math.exp(n[0]*Math.log(2));var au=(n,e)=>{n=n-57344;let t=un[n];t&&t.isShared&&((un.restoreStructures||(un.restoreStructures=[]))[n]=t),un[n]=e,e.read=ru(e)};fn[cu]=n=>{let e=n.length,t=n[1];au(n[0],t);let i={};for(let s=2;s<e;s++){let r=t[s-2];i[Ri(r)]=n[s]}return i};var __=fn[cu];fn[14]=n=>wn?wn[0].slice(wn.position0,wn.position0+=n):new Fi(n,14);fn[15]=n=>wn?wn[1].slice(wn.position1,wn.position1+=n):new Fi(n,15);var x_={Error,RegExp};fn[27]=n=>(x_[n[0]]||Error)(n[1],n[2]);var op=n=>{if(!(ie<hn))throw hi();if(ze[ie++]!=132)throw new Error("Packed values structure must be followed by a 4 element array");let e=n();if(!Array.isArray(e)||!e.length)throw new Error("Packed values structure must be followed by a 4 element array");return Vn=Vn?e.concat(Vn.slice(e.length)):e,Vn.prefixes=n(),Vn.suffixes=n(),n()};op.handlesRead=!0;fn[51]=op;fn[Kd]=n=>{if(!Vn)if(Ct.getShared)hu();else return new Fi(n,Kd);if(typeof n=="number")return Vn[16+(n>=0?2*n:-2*n-1)];throw new Error("No support for non-integer packed references yet")};fn[28]=n=>{Ai||(Ai=new Map,Ai.id=0);let e=Ai.id++,t=ie,i=ze[ie],s;i>>5==4?s=[]:s={};let r={target:s};Ai.set(e,r);let o=n();return r.used?(Object.getPrototypeOf(s)!==Object.getPrototypeOf(o)&&(ie=t,s=o,Ai.set(e,{target:s}),o=n()),Object.assign(s,o)):(r.target=o,o)};fn[28].handlesRead=!0;fn[29]=n=>{let e=Ai.get(n);return e.used=!0,e.target};fn[258]=n=>new Set(n);(fn[259]=n=>{let e=Ct;if(e.mapsAsObjects){e.mapsAsObjects=!1,ns=!0;try{return n()}finally{ns&&(e.mapsAsObjects=!0,ns=!1)}}return n()}).handlesRead=!0;function Yr(n,e){return typeof n=="string"?n+e:n instanceof Array?n.concat(e):Object.assign({},n,e)}function pr(){if(!Vn)if(Ct.getShared)hu();else throw new Error("No packed values available");return Vn}var y_=1399353956;su.push((n,e)=>{if(n>=225&&n<=255)return Yr(pr().prefixes[n-224],e);if(n>=28704&&n<=32767)return Yr(pr().prefixes[n-28672],e);if(n>=1879052288&&n<=2147483647)return Yr(pr().prefixes[n-1879048192],e);if(n>=216&&n<=223)return Yr(e,pr().suffixes[n-216]);if(n>=27647&&n<=28671)return Yr(e,pr().suffixes[n-27639]);if(n>=1811940352&&n<=1879048191)return Yr(e,pr().suffixes[n-1811939328]);if(n==y_)return{packedValues:Vn,structures:un.slice(0),version:e};if(n==55799)return e});var v_=new Uint8Array(new Uint16Array([1]).buffer)[0]==1,ep=[Uint8Array,Uint8ClampedArray,Uint16Array,Uint32Array,typeof BigUint64Array>"u"?{name:"BigUint64Array"}:BigUint64Array,Int8Array,Int16Array,Int32Array,typeof BigInt64Array>"u"?{name:"BigInt64Array"}:BigInt64Array,Float32Array,Float64Array],S_=[64,68,69,70,71,72,77,78,79,85,86];for(let n=0;n<ep.length;n++)M_(ep[n],S_[n]);function M_(n,e){let t="get"+n.name.slice(0,-5),i;typeof n=="function"?i=n.BYTES_PER_ELEMENT:n=null;for(let s=0;s<2;s++){if(!s&&i==1)continue;let r=i==2?1:i==4?2:i==8?3:0;fn[s?e:e-4]=i==1||s==v_?o=>{if(!n)throw new Error("Could not find typed array for code "+e);return!Ct.copyBuffers&&(i===1||i===2&&!(o.byteOffset&1)||i===4&&!(o.byteOffset&3)||i===8&&!(o.byteOffset&7))?new n(o.buffer,o.byteOffset,o.byteLength>>r):new n(Uint8Array.prototype.slice.call(o,0).buffer)}:o=>{if(!n)throw new Error("Could not find typed array for code "+e);let a=new DataView(o.buffer,o.byteOffset,o.byteLength),c=o.length>>r,l=new n(c),h=a[t];for(let f=0;f<c;f++)l[f]=h.call(a,f<<r,s);return l}}}function b_(){let n=$r(),e=ie+Rt();for(let i=2;i<n;i++){let s=$r();ie+=s}let t=ie;return ie=e,wn=[ou($r()),ou($r())],wn.position0=0,wn.position1=0,wn.postBundlePosition=ie,ie=t,Rt()}function $r(){if(!(ie<hn))throw hi();let n=ze[ie++]&31;if(n>23)switch(n){case 24:if(ie>=hn)throw hi();n=ze[ie++];break;case 25:if(ie+2>hn)throw hi();n=Jn.getUint16(ie),ie+=2;break;case 26:if(ie+4>hn)throw hi();n=Jn.getUint32(ie),ie+=4;break}return n}function hu(){if(Ct.getShared){let n=lu(()=>(ze=null,Ct.getShared()))||{},e=n.structures||[];Ct.sharedVersion=n.version,Vn=Ct.sharedValues=n.packedValues,un===!0?Ct.structures=un=e:un.splice.apply(un,[0,e.length].concat(e))}}function lu(n){let e=eu,t=Jo,i=sl,s=hn,r=ie,o=iu,a=ol,c=jo,l=rl,h=nu,f=Ai,u=wn,p=Vn,g=new Uint8Array(ze.slice(0,hn)),b=un,d=Ct,m=Qo,v=ns,C=al;eu=0,Jo&&(sl=Jo),Jo=null,ns=!1;try{return n()}catch(S){throw S&&(typeof S=="object"||typeof S=="function")&&ip.add(S),S}finally{eu=e,Jo=t,sl=i,hn=s,ie=r,iu=o,ol=a,jo=c,rl=l,nu=h,Ai=f,wn=u,Vn=p,ze=g,Qo=m,un=b,Ct=d,ns=v,al=C,Jn=new DataView(ze.buffer,ze.byteOffset,ze.byteLength)}}function Ko(){ze=null,Ai=null,un=null}var eu=0,Jo,zE=new Map([[cu,__],[259,fn[259]]]);var cl=new Array(147);for(let n=0;n<256;n++)cl[n]=+("1e"+Math.floor(45.15-n*.30103));var ll=new vs({useRecords:!1}),w_=ll.decode,E_=ll.decodeMultiple,hl={NEVER:0,ALWAYS:1,DECIMAL_ROUND:3,DECIMAL_FIT:4};var ul;try{ul=new TextEncoder}catch{}var mu,fp,ml=typeof globalThis=="object"&&globalThis.Buffer,ta=typeof ml<"u",uu=ta?ml.allocUnsafeSlow:Uint8Array,ap=ta?ml:Uint8Array,lp=256,cp=ta?4294967296:2144337920;var fu,Q,qt,q=0,Ss,vn=null,T_=61440,A_=/[\u0080-\uFFFF]/,ui=Symbol("record-id"),ea=class extends vs{constructor(e){super(e),this.offset=0;let t,i,s,r,o,a;e=e||{};let c=ap.prototype.utf8Write?function(y,U){return Q.utf8Write(y,U,Q.byteLength-U)}:ul&&ul.encodeInto?function(y,U){return ul.encodeInto(y,Q.subarray(U)).written}:!1,l=this,h=e.structures||e.saveStructures,f=e.maxSharedStructures;if(f==null&&(f=h?128:0),f>8190)throw new Error("Maximum maxSharedStructure is 8190");let u=e.sequential;u&&(f=0),this.structures||(this.structures=[]),this.saveStructures&&(this.saveShared=this.saveStructures);let p,g,b=e.sharedValues,d;if(b){d=Object.create(null);for(let y=0,U=b.length;y<U;y++)d[b[y]]=y}let m=[],v=0,C=0;this.mapEncode=function(y,U){return this._keyMap&&!this._mapped&&y.constructor.name==="Array"&&(y=y.map(D=>this.encodeKeys(D))),this.encode(y,U)},this.encode=function(y,U){if(Q||(Q=new uu(8192),qt=new DataView(Q.buffer,0,8192),q=0),Ss=Q.length-10,Ss-q<2048?(Q=new uu(Q.length),qt=new DataView(Q.buffer,0,Q.length),Ss=Q.length-10,q=0):U===gu&&(q=q+7&2147483640),i=q,l.useSelfDescribedHeader&&(qt.setUint32(q,3654940416),q+=3),a=l.structuredClone?new Map:null,l.bundleStrings&&typeof y!="string"?(vn=[],vn.size=1/0):vn=null,s=l.structures,s){if(s.uninitialized){let A=l.getShared()||{};l.structures=s=A.structures||[],l.sharedVersion=A.version;let z=l.sharedValues=A.packedValues;if(z){d={};for(let B=0,H=z.length;B<H;B++)d[z[B]]=B}}let D=s.length;if(D>f&&!u&&(D=f),!s.transitions){s.transitions=Object.create(null);for(let A=0;A<D;A++){let z=s[A];if(!z)continue;let B,H=s.transitions;for(let $=0,ne=z.length;$<ne;$++){H[ui]===void 0&&(H[ui]=A);let oe=z[$];B=H[oe],B||(B=H[oe]=Object.create(null)),H=B}H[ui]=A|1048576}}u||(s.nextId=D)}if(r&&(r=!1),o=s||[],g=d,e.pack){let D=new Map;if(D.values=[],D.encoder=l,D.maxValues=e.maxPrivatePackedValues||(d?16:1/0),D.objectMap=d||!1,D.samplingPackedValues=p,fl(y,D),D.values.length>0){Q[q++]=216,Q[q++]=51,ss(4);let A=D.values;S(A),ss(0),ss(0),g=Object.create(d||null);for(let z=0,B=A.length;z<B;z++)g[A[z]]=z}}fu=U&pu;try{if(fu)return;if(S(y),vn&&vn.position&&up(i,S),l.offset=q,a&&a.idsToInsert){q+=a.idsToInsert.length*2,q>Ss&&T(q),l.offset=q;let D=P_(Q.subarray(i,q),a.idsToInsert);return a=null,D}return U&gu?(Q.start=i,Q.end=q,Q):Q.subarray(i,q)}finally{if(s){if(C<10&&C++,s.length>f&&(s.length=f),v>1e4)s.transitions=null,C=0,v=0,m.length>0&&(m=[]);else if(m.length>0&&!u){for(let D=0,A=m.length;D<A;D++)m[D][ui]=void 0;m=[]}}if(r&&l.saveShared){l.structures.length>f&&(l.structures=l.structures.slice(0,f));let D=Q.subarray(i,q);return l.updateSharedData()===!1?l.encode(y):D}U&B_&&(q=i)}},this.findCommonStringsToPack=()=>(p=new Map,d||(d=Object.create(null)),y=>{let U=y&&y.threshold||4,D=this.pack?y.maxPrivatePackedValues||16:0;b||(b=this.sharedValues=[]);for(let[A,z]of p)z.count>U&&(d[A]=D++,b.push(A),r=!0);for(;this.saveShared&&this.updateSharedData()===!1;);p=null});let S=y=>{q>Ss&&(Q=T(q));var U=typeof y,D;if(U==="string"){if(g){let H=g[y];if(H>=0){H<16?Q[q++]=H+224:(Q[q++]=198,H&1?S(15-H>>1):S(H-16>>1));return}else if(p&&!e.pack){let $=p.get(y);$?$.count++:p.set(y,{count:1})}}let A=y.length;if(vn&&A>=4&&A<1024){if((vn.size+=A)>T_){let $,ne=(vn[0]?vn[0].length*3+vn[1].length:0)+10;q+ne>Ss&&(Q=T(q+ne)),Q[q++]=217,Q[q++]=223,Q[q++]=249,Q[q++]=vn.position?132:130,Q[q++]=26,$=q-i,q+=4,vn.position&&up(i,S),vn=["",""],vn.size=0,vn.position=$}let H=A_.test(y);vn[H?0:1]+=y,Q[q++]=H?206:207,S(A);return}let z;A<32?z=1:A<256?z=2:A<65536?z=3:z=5;let B=A*3;if(q+B>Ss&&(Q=T(q+B)),A<64||!c){let H,$,ne,oe=q+z;for(H=0;H<A;H++)$=y.charCodeAt(H),$<128?Q[oe++]=$:$<2048?(Q[oe++]=$>>6|192,Q[oe++]=$&63|128):($&64512)===55296&&((ne=y.charCodeAt(H+1))&64512)===56320?($=65536+(($&1023)<<10)+(ne&1023),H++,Q[oe++]=$>>18|240,Q[oe++]=$>>12&63|128,Q[oe++]=$>>6&63|128,Q[oe++]=$&63|128):(Q[oe++]=$>>12|224,Q[oe++]=$>>6&63|128,Q[oe++]=$&63|128);D=oe-q-z}else D=c(y,q+z,B);D<24?Q[q++]=96|D:D<256?(z<2&&Q.copyWithin(q+2,q+1,q+1+D),Q[q++]=120,Q[q++]=D):D<65536?(z<3&&Q.copyWithin(q+3,q+2,q+2+D),Q[q++]=121,Q[q++]=D>>8,Q[q++]=D&255):(z<5&&Q.copyWithin(q+5,q+3,q+3+D),Q[q++]=122,qt.setUint32(q,D),q+=4),q+=D}else if(U==="number")if(!this.alwaysUseFloat&&y>>>0===y)y<24?Q[q++]=y:y<256?(Q[q++]=24,Q[q++]=y):y<65536?(Q[q++]=25,Q[q++]=y>>8,Q[q++]=y&255):(Q[q++]=26,qt.setUint32(q,y),q+=4);else if(!this.alwaysUseFloat&&y>>0===y)y>=-24?Q[q++]=31-y:y>=-256?(Q[q++]=56,Q[q++]=~y):y>=-65536?(Q[q++]=57,qt.setUint16(q,~y),q+=2):(Q[q++]=58,qt.setUint32(q,~y),q+=4);else if(!this.alwaysUseFloat&&y<0&&y>=-4294967296&&Math.floor(y)===y)Q[q++]=58,qt.setUint32(q,-1-y),q+=4;else{let A;if((A=this.useFloat32)>0&&y<4294967296&&y>=-2147483648){Q[q++]=250,qt.setFloat32(q,y);let z;if(A<4||(z=y*cl[(Q[q]&127)<<1|Q[q+1]>>7])>>0===z){q+=4;return}else q--}Q[q++]=251,qt.setFloat64(q,y),q+=8}else if(U==="object")if(!y)Q[q++]=246;else{if(a){let z=a.get(y);if(z){if(Q[q++]=216,Q[q++]=29,Q[q++]=25,!z.references){let B=a.idsToInsert||(a.idsToInsert=[]);z.references=[],B.push(z)}z.references.push(q-i),q+=2;return}else a.set(y,{offset:q-i})}let A=y.constructor;if(A===Object)this.skipFunction===!0&&(y=Object.fromEntries([...Object.keys(y).filter(z=>typeof y[z]!="function").map(z=>[z,y[z]])])),P(y);else if(A===Array){D=y.length,D<24?Q[q++]=128|D:ss(D);for(let z=0;z<D;z++)S(y[z])}else if(A===Map)if((this.mapsAsObjects?this.useTag259ForMaps!==!1:this.useTag259ForMaps)&&(Q[q++]=217,Q[q++]=1,Q[q++]=3),D=y.size,D<24?Q[q++]=160|D:D<256?(Q[q++]=184,Q[q++]=D):D<65536?(Q[q++]=185,Q[q++]=D>>8,Q[q++]=D&255):(Q[q++]=186,qt.setUint32(q,D),q+=4),l.keyMap)for(let[z,B]of y)S(l.encodeKey(z)),S(B);else for(let[z,B]of y)S(z),S(B);else{for(let z=0,B=mu.length;z<B;z++){let H=fp[z];if(y instanceof H){let $=mu[z],ne=$.tag;ne==null&&(ne=$.getTag&&$.getTag.call(this,y)),ne<24?Q[q++]=192|ne:ne<256?(Q[q++]=216,Q[q++]=ne):ne<65536?(Q[q++]=217,Q[q++]=ne>>8,Q[q++]=ne&255):ne>-1&&(Q[q++]=218,qt.setUint32(q,ne),q+=4),$.encode.call(this,y,S,T);return}}if(y[Symbol.iterator]){if(fu){let z=new Error("Iterable should be serialized as iterator");throw z.iteratorNotHandled=!0,z}Q[q++]=159;for(let z of y)S(z);Q[q++]=255;return}if(y[Symbol.asyncIterator]||du(y)){let z=new Error("Iterable/blob should be serialized as iterator");throw z.iteratorNotHandled=!0,z}if(this.useToJSON&&y.toJSON){let z=y.toJSON();if(z!==y)return S(z)}if(A===DataView){pl(new Uint8Array(y.buffer,y.byteOffset,y.byteLength),T);return}P(y)}}else if(U==="boolean")Q[q++]=y?245:244;else if(U==="bigint"){if(y<BigInt(1)<<BigInt(64)&&y>=0)Q[q++]=27,qt.setBigUint64(q,y);else if(y>-(BigInt(1)<<BigInt(64))&&y<0)Q[q++]=59,qt.setBigUint64(q,-y-BigInt(1));else if(this.largeBigIntToFloat)Q[q++]=251,qt.setFloat64(q,Number(y));else{y>=BigInt(0)?Q[q++]=194:(Q[q++]=195,y=BigInt(-1)-y);let A=[];for(;y;)A.push(Number(y&BigInt(255))),y>>=BigInt(8);pl(new Uint8Array(A.reverse()),T);return}q+=8}else if(U==="undefined")Q[q++]=247;else throw new Error("Unknown type: "+U)},P=this.useRecords===!1?this.variableMapSize?y=>{let U=Object.keys(y),D=Object.values(y),A=U.length;A<24?Q[q++]=160|A:A<256?(Q[q++]=184,Q[q++]=A):A<65536?(Q[q++]=185,Q[q++]=A>>8,Q[q++]=A&255):(Q[q++]=186,qt.setUint32(q,A),q+=4);let z;if(l.keyMap)for(let B=0;B<A;B++)S(l.encodeKey(U[B])),S(D[B]);else for(let B=0;B<A;B++)S(U[B]),S(D[B])}:y=>{Q[q++]=185;let U=q-i;q+=2;let D=0;if(l.keyMap)for(let A in y)(typeof y.hasOwnProperty!="function"||y.hasOwnProperty(A))&&(S(l.encodeKey(A)),S(y[A]),D++);else for(let A in y)(typeof y.hasOwnProperty!="function"||y.hasOwnProperty(A))&&(S(A),S(y[A]),D++);if(D<65536)Q[U+++i]=D>>8,Q[U+i]=D&255;else{q+2>Ss&&T(q+2);let A=U+i;Q.copyWithin(A+4,A+2,q),q+=2,Q[A-1]=186,qt.setUint32(A,D)}}:(y,U)=>{let D,A=o.transitions||(o.transitions=Object.create(null)),z=0,B=0,H,$;if(this.keyMap){$=Object.keys(y).map(oe=>this.encodeKey(oe)),B=$.length;for(let oe=0;oe<B;oe++){let se=$[oe];D=A[se],D||(D=A[se]=Object.create(null),z++),A=D}}else for(let oe in y)(typeof y.hasOwnProperty!="function"||y.hasOwnProperty(oe))&&(D=A[oe],D||(A[ui]&1048576&&(H=A[ui]&65535),D=A[oe]=Object.create(null),z++),A=D,B++);let ne=A[ui];if(ne!==void 0)ne&=65535,Q[q++]=217,Q[q++]=ne>>8|224,Q[q++]=ne&255;else if($||($=A.__keys__||(A.__keys__=Object.keys(y))),H===void 0?(ne=o.nextId++,ne||(ne=0,o.nextId=1),ne>=lp&&(o.nextId=(ne=f)+1)):ne=H,o[ne]=$,ne<f){Q[q++]=217,Q[q++]=ne>>8|224,Q[q++]=ne&255,A=o.transitions;for(let oe=0;oe<B;oe++)(A[ui]===void 0||A[ui]&1048576)&&(A[ui]=ne),A=A[$[oe]];A[ui]=ne|1048576,r=!0}else{if(A[ui]=ne,qt.setUint32(q,3655335680),q+=3,z&&(v+=C*z),m.length>=lp-f&&(m.shift()[ui]=void 0),m.push(A),ss(B+2),S(57344+ne),S($),U)return;for(let oe in y)(typeof y.hasOwnProperty!="function"||y.hasOwnProperty(oe))&&S(y[oe]);return}if(B<24?Q[q++]=128|B:ss(B),!U)for(let oe in y)(typeof y.hasOwnProperty!="function"||y.hasOwnProperty(oe))&&S(y[oe])},T=y=>{let U;if(y>16777216){if(y-i>cp)throw new Error("Encoded buffer would be larger than maximum buffer size");U=Math.min(cp,Math.round(Math.max((y-i)*(y>67108864?1.25:2),4194304)/4096)*4096)}else U=(Math.max(y-i<<2,Q.length-1)>>12)+1<<12;let D=new uu(U);return qt=new DataView(D.buffer,0,U),Q.copy?Q.copy(D,0,i,y):D.set(Q.slice(i,y)),q-=i,i=0,Ss=D.length-10,Q=D},_=100,R=1e3;this.encodeAsIterable=function(y,U){return G(y,U,W)},this.encodeAsAsyncIterable=function(y,U){return G(y,U,X)};function*W(y,U,D){let A=y.constructor;if(A===Object){let z=l.useRecords!==!1;z?P(y,!0):hp(Object.keys(y).length,160);for(let B in y){let H=y[B];z||S(B),H&&typeof H=="object"?U[B]?yield*W(H,U[B]):yield*O(H,U,B):S(H)}}else if(A===Array){let z=y.length;ss(z);for(let B=0;B<z;B++){let H=y[B];H&&(typeof H=="object"||q-i>_)?U.element?yield*W(H,U.element):yield*O(H,U,"element"):S(H)}}else if(y[Symbol.iterator]&&!y.buffer){Q[q++]=159;for(let z of y)z&&(typeof z=="object"||q-i>_)?U.element?yield*W(z,U.element):yield*O(z,U,"element"):S(z);Q[q++]=255}else du(y)?(hp(y.size,64),yield Q.subarray(i,q),yield y,L()):y[Symbol.asyncIterator]?(Q[q++]=159,yield Q.subarray(i,q),yield y,L(),Q[q++]=255):S(y);D&&q>i?yield Q.subarray(i,q):q-i>_&&(yield Q.subarray(i,q),L())}function*O(y,U,D){let A=q-i;try{S(y),q-i>_&&(yield Q.subarray(i,q),L())}catch(z){if(z.iteratorNotHandled)U[D]={},q=i+A,yield*W.call(this,y,U[D]);else throw z}}function L(){_=R,l.encode(null,pu)}function G(y,U,D){return U&&U.chunkThreshold?_=R=U.chunkThreshold:_=100,y&&typeof y=="object"?(l.encode(null,pu),D(y,l.iterateProperties||(l.iterateProperties={}),!0)):[l.encode(y)]}async function*X(y,U){for(let D of W(y,U,!0)){let A=D.constructor;if(A===ap||A===Uint8Array)yield D;else if(du(D)){let z=D.stream().getReader(),B;for(;!(B=await z.read()).done;)yield B.value}else if(D[Symbol.asyncIterator])for await(let z of D)L(),z?yield*X(z,U.async||(U.async={})):yield l.encode(z);else yield D}}}useBuffer(e){Q=e,qt=new DataView(Q.buffer,Q.byteOffset,Q.byteLength),q=0}clearSharedData(){this.structures&&(this.structures=[]),this.sharedValues&&(this.sharedValues=void 0)}updateSharedData(){let e=this.sharedVersion||0;this.sharedVersion=e+1;let t=this.structures.slice(0),i=new dl(t,this.sharedValues,this.sharedVersion),s=this.saveShared(i,r=>(r&&r.version||0)==e);return s===!1?(i=this.getShared()||{},this.structures=i.structures||[],this.sharedValues=i.packedValues,this.sharedVersion=i.version,this.structures.nextId=this.structures.length):t.forEach((r,o)=>this.structures[o]=r),s}};function hp(n,e){n<24?Q[q++]=e|n:n<256?(Q[q++]=e|24,Q[q++]=n):n<65536?(Q[q++]=e|25,Q[q++]=n>>8,Q[q++]=n&255):(Q[q++]=e|26,qt.setUint32(q,n),q+=4)}var dl=class{constructor(e,t,i){this.structures=e,this.packedValues=t,this.version=i}};function ss(n){n<24?Q[q++]=128|n:n<256?(Q[q++]=152,Q[q++]=n):n<65536?(Q[q++]=153,Q[q++]=n>>8,Q[q++]=n&255):(Q[q++]=154,qt.setUint32(q,n),q+=4)}var R_=typeof Blob>"u"?function(){}:Blob;function du(n){if(n instanceof R_)return!0;let e=n[Symbol.toStringTag];return e==="Blob"||e==="File"}function fl(n,e){switch(typeof n){case"string":if(n.length>3){if(e.objectMap[n]>-1||e.values.length>=e.maxValues)return;let i=e.get(n);if(i)++i.count==2&&e.values.push(n);else if(e.set(n,{count:1}),e.samplingPackedValues){let s=e.samplingPackedValues.get(n);s?s.count++:e.samplingPackedValues.set(n,{count:1})}}break;case"object":if(n)if(n instanceof Array)for(let i=0,s=n.length;i<s;i++)fl(n[i],e);else{let i=!e.encoder.useRecords;for(var t in n)n.hasOwnProperty(t)&&(i&&fl(t,e),fl(n[t],e))}break;case"function":console.log(n)}}var C_=new Uint8Array(new Uint16Array([1]).buffer)[0]==1;fp=[Date,Set,Error,RegExp,Fi,ArrayBuffer,Uint8Array,Uint8ClampedArray,Uint16Array,Uint32Array,typeof BigUint64Array>"u"?function(){}:BigUint64Array,Int8Array,Int16Array,Int32Array,typeof BigInt64Array>"u"?function(){}:BigInt64Array,Float32Array,Float64Array,dl];mu=[{tag:1,encode(n,e){let t=n.getTime()/1e3;(this.useTimestamp32||n.getMilliseconds()===0)&&t>=0&&t<4294967296?(Q[q++]=26,qt.setUint32(q,t),q+=4):(Q[q++]=251,qt.setFloat64(q,t),q+=8)}},{tag:258,encode(n,e){let t=Array.from(n);e(t)}},{tag:27,encode(n,e){e([n.name,n.message])}},{tag:27,encode(n,e){e(["RegExp",n.source,n.flags])}},{getTag(n){return n.tag},encode(n,e){e(n.value)}},{encode(n,e,t){pl(n,t)}},{getTag(n){if(n.constructor===Uint8Array&&(this.tagUint8Array||ta&&this.tagUint8Array!==!1))return 64},encode(n,e,t){pl(n,t)}},is(68,1),is(69,2),is(70,4),is(71,8),is(72,1),is(77,2),is(78,4),is(79,8),is(85,4),is(86,8),{encode(n,e){let t=n.packedValues||[],i=n.structures||[];if(t.values.length>0){Q[q++]=216,Q[q++]=51,ss(4);let s=t.values;e(s),ss(0),ss(0),packedObjectMap=Object.create(sharedPackedObjectMap||null);for(let r=0,o=s.length;r<o;r++)packedObjectMap[s[r]]=r}if(i){qt.setUint32(q,3655335424),q+=3;let s=i.slice(0);s.unshift(57344),s.push(new Fi(n.version,1399353956)),e(s)}else e(new Fi(n.version,1399353956))}}];function is(n,e){return!C_&&e>1&&(n-=4),{tag:n,encode:function(i,s){let r=i.byteLength,o=i.byteOffset||0,a=i.buffer||i;s(ta?ml.from(a,o,r):new Uint8Array(a,o,r))}}}function pl(n,e){let t=n.byteLength;t<24?Q[q++]=64+t:t<256?(Q[q++]=88,Q[q++]=t):t<65536?(Q[q++]=89,Q[q++]=t>>8,Q[q++]=t&255):(Q[q++]=90,qt.setUint32(q,t),q+=4),q+t>=Q.length&&e(q+t),Q.set(n.buffer?n:new Uint8Array(n),q),q+=t}function P_(n,e){let t,i=e.length*2,s=n.length-i;e.sort((r,o)=>r.offset>o.offset?1:-1);for(let r=0;r<e.length;r++){let o=e[r];o.id=r;for(let a of o.references)n[a++]=r>>8,n[a]=r&255}for(;t=e.pop();){let r=t.offset;n.copyWithin(r+i,r,s),i-=2;let o=r+i;n[o++]=216,n[o++]=28,s=r}return n}function up(n,e){qt.setUint32(vn.position+n,q-vn.position-n+1);let t=vn;vn=null,e(t[0]),e(t[1])}var _u=new ea({useRecords:!1}),I_=_u.encode,L_=_u.encodeAsIterable,D_=_u.encodeAsAsyncIterable,{NEVER:N_,ALWAYS:U_,DECIMAL_ROUND:F_,DECIMAL_FIT:O_}=hl,gu=512,B_=1024,pu=2048;var z_=new vs({int64AsNumber:!0,mapsAsObjects:!0,useRecords:!1});function V_(n){let e=n instanceof Uint8Array?n:new Uint8Array(n);return z_.decode(e)}var Hs=class extends Error{},gl=class{constructor(e){this.url=e;this.connect()}url;ws=null;subs=new Map;pending=new Map;goals=new Map;statusWaiters=new Map;nextId=1;closed=!1;retryMs=500;onState=()=>{};framesIn=0;bytesIn=0;connect(){this.onState("connecting");let e=new WebSocket(this.url);e.binaryType="arraybuffer",this.ws=e,e.onopen=()=>{this.retryMs=500,this.onState("open");for(let t of this.subs.values())this.sendSubscribe(t)},e.onmessage=t=>this.onFrame(t.data),e.onclose=t=>{this.onState("closed",t.reason||`code ${t.code}`);for(let[i,s]of this.pending)clearTimeout(s.timer),s.reject(new Error("connection to the hub lost")),this.pending.delete(i);this.closed||(setTimeout(()=>this.connect(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))}}close(){this.closed=!0,this.ws?.close()}send(e){this.ws?.readyState===WebSocket.OPEN&&this.ws.send(JSON.stringify(e))}onFrame(e){let t=performance.now();this.framesIn++;let i,s=typeof e=="string"?e.length:e.byteLength;try{typeof e=="string"?(this.bytesIn+=e.length,i=JSON.parse(e)):(this.bytesIn+=e.byteLength,i=V_(e)),Ot.busyMs.decode+=performance.now()-t}catch(r){console.warn("undecodable frame from the hub",r);return}switch(i.op){case"publish":{let r=String(i.topic);for(let o of this.subs.values())if(o.topic===r||o.opts.regex&&new RegExp(`^(?:${o.topic})$`).test(r))for(let a of o.handlers)try{a(i.msg,r,t,s)}catch(c){console.error(`handler for ${r} failed`,c)}break}case"service_response":{let r=this.pending.get(String(i.id));if(!r)break;this.pending.delete(String(i.id)),clearTimeout(r.timer),i.result===!1?r.reject(new Hs(typeof i.values=="string"?i.values:JSON.stringify(i.values))):r.resolve(i.values);break}case"action_feedback":{this.goals.get(String(i.id))?.onFeedback(i.values);break}case"action_result":{let r=this.goals.get(String(i.id));if(!r)break;this.goals.delete(String(i.id)),r.done.resolve({status:i.status,values:i.values,result:i.result});break}case"status":{let r=i.id===void 0?void 0:String(i.id);if(i.level==="error"&&r){let o=this.pending.get(r);o&&(this.pending.delete(r),clearTimeout(o.timer),o.reject(new Hs(String(i.msg))));let a=this.goals.get(r);a&&(this.goals.delete(r),a.done.reject(new Hs(String(i.msg)))),this.statusWaiters.get(r)?.(String(i.msg))}i.level==="error"&&!r&&console.warn("hub:",i.msg);break}}}sendSubscribe(e){this.send({op:"subscribe",id:`sub:${e.topic}`,topic:e.topic,type:e.opts.type,compression:e.opts.compression??"cbor",queue_length:e.opts.queue_length??1,throttle_rate:e.opts.throttle_rate??0,regex:e.opts.regex||void 0})}subscribe(e,t,i={}){let s=this.subs.get(e);return s||(s={topic:e,opts:i,handlers:new Set},this.subs.set(e,s),this.sendSubscribe(s)),s.handlers.add(t),()=>{let r=this.subs.get(e);r&&(r.handlers.delete(t),r.handlers.size===0&&(this.subs.delete(e),this.send({op:"unsubscribe",id:`sub:${e}`,topic:e})))}}call(e,t={},i=10){let s=`call:${this.nextId++}`;return new Promise((r,o)=>{let a=window.setTimeout(()=>{this.pending.delete(s),o(new Error(`${e}: no answer within ${i+2} s`))},(i+2)*1e3);this.pending.set(s,{resolve:r,reject:o,timer:a}),this.send({op:"call_service",id:s,service:e,args:t,timeout:i})})}advertise(e,t,i=1500){let s=`adv:${e}:${this.nextId++}`;return new Promise(r=>{let o=window.setTimeout(()=>{this.statusWaiters.delete(s),r(null)},i);this.statusWaiters.set(s,a=>{clearTimeout(o),this.statusWaiters.delete(s),r(a)}),this.send({op:"advertise",id:s,topic:e,type:t})})}unadvertise(e){this.send({op:"unadvertise",topic:e})}publish(e,t,i){let s=`pub:${e}:${this.nextId++}`;i&&(this.statusWaiters.set(s,r=>{this.statusWaiters.delete(s),i(r)}),setTimeout(()=>this.statusWaiters.delete(s),5e3)),this.send({op:"publish",id:s,topic:e,msg:t})}sendGoal(e,t,i,s){let r=`goal:${this.nextId++}`,o=new Promise((a,c)=>{this.goals.set(r,{onFeedback:s,done:{resolve:a,reject:c,timer:0}})});return this.send({op:"send_action_goal",id:r,action:e,action_type:t,args:i,feedback:!0}),{id:r,result:o,cancel:()=>this.send({op:"cancel_action_goal",id:r,action:e})}}};function ye(n,e="",t){let i=document.createElement(n);return e&&(i.className=e),t!==void 0&&(i.textContent=t),i}function mn(n,e=1){return n==null||!Number.isFinite(n)?"–":Math.abs(n)>=100?n.toFixed(0):n.toFixed(e)}function Zr(n){if(n==null||!Number.isFinite(n)||n<=0)return"–";let e=["B/s","kB/s","MB/s","GB/s"],t=n,i=0;for(;t>=1e3&&i<e.length-1;)t/=1e3,i++;return`${t.toFixed(t>=100?0:1)} ${e[i]}`}function xu(n){if(!n)return"never";let e=Math.max(0,(Date.now()-n)/1e3);return e<2?"just now":e<90?`${e.toFixed(0)} s ago`:e<5400?`${(e/60).toFixed(0)} min ago`:new Date(n).toLocaleString()}function Gs(n,e="",t){let i=ye("button",e,n);return t&&i.addEventListener("click",t),i}function na(n,e="",t=0){if(n!==null&&typeof n=="object"){let s=ye("details");t<2&&(s.open=!0);let r=Object.entries(n);s.appendChild(ye("summary","",`${e}${e?": ":""}${Array.isArray(n)?`[${r.length}]`:`{${r.length}}`}`));for(let[o,a]of r)s.appendChild(na(a,o,t+1));return s}let i=ye("div","leaf");return i.appendChild(ye("span","key",e?`${e}: `:"")),i.appendChild(ye("span",`val ${typeof n}`,JSON.stringify(n)??String(n))),i}function dp(n){n.innerHTML="";let e=ye("div","admin"),t=ye("section","panel wide");t.appendChild(ye("h2","","Audit log"));let i=ye("form","filters"),s={};for(let[v,C]of[["principal","user:alice"],["action","publish"],["name_regex","/robot1/.*"]]){let S=ye("input");S.name=v,S.placeholder=`${v} e.g. ${C}`,s[v]=S,i.appendChild(S)}let r=ye("select");r.name="allowed";for(let[v,C]of[["","allowed and denied"],["true","allowed only"],["false","denied only"]])r.appendChild(new Option(C,v));s.allowed=r,i.appendChild(r);let o=Gs("Filter","primary");o.type="submit",i.appendChild(o);let a=ye("table","audit"),c=ye("div","pager"),l=Gs("Next page →"),h=Gs("⇤ First page"),f=ye("span","muted");c.append(h,l,f),t.append(i,a,c);let u=ye("section","panel wide");u.appendChild(ye("h2","","Access rules"));let p=ye("div");u.appendChild(p),e.append(t,u),n.appendChild(e);let g=50,b=[null],d=0;async function m(){let v=new URLSearchParams({limit:String(g)});for(let[S,P]of Object.entries(s))P.value&&v.set(S,P.value);let C=b[d];C!=null&&v.set("cursor",typeof C=="string"?C:JSON.stringify(C));try{let S=await Ti(`/api/v1/audit?${v}`);a.innerHTML="<thead><tr><th>time</th><th>principal</th><th>client</th><th>action</th><th>name</th><th>size</th><th>allowed</th><th>detail</th></tr></thead>";let P=ye("tbody");for(let T of S.records){let _=ye("tr",T.allowed?"":"denied"),R=T.at?.secs!=null?T.at.secs*1e3:typeof T.at=="number"?T.at>1e12?T.at:T.at*1e3:NaN;for(let W of[Number.isFinite(R)?new Date(R).toLocaleString():JSON.stringify(T.at),T.principal,T.client_ip,T.action,T.name,T.size??"",T.allowed?"yes":"no",T.detail??""])_.appendChild(ye("td","",String(W)));P.appendChild(_)}a.appendChild(P),b=b.slice(0,d+1),S.next!=null&&b.push(S.next),l.disabled=S.next==null,h.disabled=d===0,f.textContent=`page ${d+1} · ${S.records.length} records`}catch(S){a.replaceChildren(ye("caption","why",`The hub refused the audit log: ${S.message}`)),l.disabled=h.disabled=!0}}return i.addEventListener("submit",v=>{v.preventDefault(),b=[null],d=0,m()}),l.addEventListener("click",()=>{d++,m()}),h.addEventListener("click",()=>{d=0,m()}),m(),Ti("/api/v1/rules").then(v=>{let C=ye("table","rules");C.innerHTML="<thead><tr><th>id</th><th>subject</th><th>names</th><th>ops</th><th>effect</th><th>comment</th></tr></thead>";let S=ye("tbody");for(let P of v.rules){let T=P.rule??P,_=ye("tr"),R=T.subject&&typeof T.subject=="object"?Object.entries(T.subject).map(([W,O])=>`${W}:${O}`).join(" "):T.subject;for(let W of[P.id??"",R,T.names,Array.isArray(T.ops)?T.ops.join(", "):T.ops,T.effect??"allow",T.comment??""])_.appendChild(ye("td","",typeof W=="string"||typeof W=="number"?String(W):JSON.stringify(W)));S.appendChild(_)}C.appendChild(S),p.replaceChildren(v.rules.length?C:ye("p","muted","No rules: only the built-in defaults apply (admin group, robots' own namespaces, anonymous read where enabled)."))},v=>p.replaceChildren(ye("p","why",`The hub refused the rules: ${v.message}`))),()=>{}}function yu(n){if(n instanceof Uint8Array)return n;if(ArrayBuffer.isView(n))return new Uint8Array(n.buffer,n.byteOffset,n.byteLength);if(typeof n=="string"){let e=atob(n),t=new Uint8Array(e.length);for(let i=0;i<e.length;i++)t[i]=e.charCodeAt(i);return t}return Array.isArray(n)?Uint8Array.from(n):new Uint8Array(0)}function yl(n){let e=n?.stamp;if(!e)return null;let t=e.sec??e.secs,i=e.nanosec??e.nsecs??0;return typeof t=="number"?t*1e3+i/1e6:null}function H_(n){return Math.atan2(2*(n.w*n.z+n.x*n.y),1-2*(n.y*n.y+n.z*n.z))}function vl(n){let e=n?.pose;return e?.pose&&(e=e.pose),!e?.position||!e?.orientation?null:{x:e.position.x,y:e.position.y,yaw:H_(e.orientation)}}function mp(n){let e=n.ranges??[],t=new Float32Array(e.length*2),i=0;for(let s=0;s<e.length;s++){let r=e[s];if(!(r>=n.range_min&&r<=n.range_max))continue;let o=n.angle_min+s*n.angle_increment;t[i++]=r*Math.cos(o),t[i++]=r*Math.sin(o)}return t.subarray(0,i)}var _l={1:[1,(n,e)=>n.getInt8(e)],2:[1,(n,e)=>n.getUint8(e)],3:[2,(n,e,t)=>n.getInt16(e,t)],4:[2,(n,e,t)=>n.getUint16(e,t)],5:[4,(n,e,t)=>n.getInt32(e,t)],6:[4,(n,e,t)=>n.getUint32(e,t)],7:[4,(n,e,t)=>n.getFloat32(e,t)],8:[8,(n,e,t)=>n.getFloat64(e,t)]};function gp(n,e){let t=yu(n.data),i=(n.width??0)*(n.height??1),s=n.point_step,r=!n.is_bigendian,o=_=>n.fields.find(R=>R.name===_),a=o("x"),c=o("y"),l=o("z"),h=o("intensity");if(!a||!c||!l||!s)throw new Error("PointCloud2 without x, y, z fields");let f=e&&e.positions.length>=i*3?e.positions:new Float32Array(i*3),u=e&&e.intensity.length>=i?e.intensity:new Float32Array(i),p=new DataView(t.buffer,t.byteOffset,t.byteLength),g=r&&a.datatype===7&&c.datatype===7&&l.datatype===7,b=_l[a.datatype][1],d=_l[c.datatype][1],m=_l[l.datatype][1],v=h?_l[h.datatype]?.[1]:void 0,C=n.height??1,S=n.width??0,P=n.row_step||S*s,T=0;for(let _=0;_<C;_++)for(let R=0;R<S;R++){let W=_*P+R*s;if(W+s>t.byteLength)break;let O=g?p.getFloat32(W+a.offset,!0):b(p,W+a.offset,r),L=g?p.getFloat32(W+c.offset,!0):d(p,W+c.offset,r),G=g?p.getFloat32(W+l.offset,!0):m(p,W+l.offset,r);!Number.isFinite(O)||!Number.isFinite(L)||!Number.isFinite(G)||(f[T*3]=O,f[T*3+1]=L,f[T*3+2]=G,u[T]=v?v(p,W+h.offset,r):NaN,T++)}return{positions:f,intensity:u,count:T}}function _p(n){return n.length>3&&n[0]===255&&n[1]===216&&n[2]===255?"jpeg":n.length>8&&n[0]===137&&n[1]===80&&n[2]===78&&n[3]===71?"png":"unknown"}function xl(n,e=64){if(n instanceof Uint8Array)return`<${n.length} bytes>`;if(ArrayBuffer.isView(n)){let t=Array.from(n).slice(0,e),i=n.length;return i>e?[...t,`… ${i-e} more (${n.constructor.name})`]:t}if(Array.isArray(n)){let t=n.slice(0,e).map(i=>xl(i,e));return n.length>e?[...t,`… ${n.length-e} more`]:t}if(n&&typeof n=="object"){let t={};for(let[i,s]of Object.entries(n))t[i]=xl(s,e);return t}return n}var pp={bool:!1,string:"",float32:0,float64:0,int8:0,uint8:0,int16:0,uint16:0,int32:0,uint32:0,int64:0,uint64:0,byte:0,char:0,time:{sec:0,nanosec:0},duration:{sec:0,nanosec:0}};function xp(n,e){let t=e?n.find(s=>s.type===e):n[0],i=(s,r)=>{let o={};return!s||r>16||s.fieldnames.forEach((a,c)=>{let l=s.fieldtypes[c],h=s.fieldarraylen?.[c]??-1,f=l in pp?pp[l]:i(n.find(u=>u.type===l),r+1);o[a]=h===-1?f:h===0?[]:Array.from({length:h},()=>f)}),o};return i(t,0)}var yp=["#2f80ed","#eb5757","#27ae60","#f2994a","#9b51e0","#56ccf2","#bb6bd9","#219653"];function vp(n){return yp[n%yp.length]}var Jr=class{canvas=document.createElement("canvas");robots=new Map;scan=null;goal=null;selected=null;onClick=null;half=11;dirty=!0;raf=0;ro;constructor(e){this.canvas.className="map",e.appendChild(this.canvas),this.ro=new ResizeObserver(()=>this.invalidate()),this.ro.observe(this.canvas),this.canvas.addEventListener("click",i=>{if(!this.onClick)return;let[s,r]=this.toWorld(i.offsetX,i.offsetY);this.onClick(s,r,i)});let t=()=>{this.dirty&&this.draw(),this.raf=requestAnimationFrame(t)};this.raf=requestAnimationFrame(t)}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.canvas.remove()}invalidate(){this.dirty=!0}setPose(e,t,i){let s=this.robots.get(e);s||(s={name:e,pose:null,trail:[],online:!0,colour:i},this.robots.set(e,s));let r=performance.now();s.pose=t;let o=s.trail[s.trail.length-1];for((!o||Math.hypot(o.x-t.x,o.y-t.y)>.05||r-o.t>500)&&s.trail.push({x:t.x,y:t.y,t:r});s.trail.length&&r-s.trail[0].t>6e4;)s.trail.shift();let a=Math.max(Math.abs(t.x),Math.abs(t.y))+1;a>this.half&&(this.half=Math.ceil(a)),this.invalidate()}geometry(){let e=window.devicePixelRatio||1,t=this.canvas.clientWidth,i=this.canvas.clientHeight,s=Math.min(t,i)/(2*this.half);return{dpr:e,w:t,h:i,scale:s,cx:t/2,cy:i/2}}toWorld(e,t){let i=this.geometry();return[(e-i.cx)/i.scale,-(t-i.cy)/i.scale]}toScreen(e,t){let i=this.geometry();return[i.cx+e*i.scale,i.cy-t*i.scale]}draw(){this.dirty=!1;let e=this.geometry();if(e.w===0||e.h===0)return;(this.canvas.width!==Math.round(e.w*e.dpr)||this.canvas.height!==Math.round(e.h*e.dpr))&&(this.canvas.width=Math.round(e.w*e.dpr),this.canvas.height=Math.round(e.h*e.dpr));let t=this.canvas.getContext("2d");t.setTransform(e.dpr,0,0,e.dpr,0,0),t.fillStyle="#0f1720",t.fillRect(0,0,e.w,e.h);let i=(s,r)=>[e.cx+s*e.scale,e.cy-r*e.scale];for(let s=-this.half;s<=this.half;s++){t.strokeStyle=s===0?"#3b4a5a":s%5===0?"#24313e":"#18222c",t.lineWidth=1;let[r,o]=i(s,-this.half),[a,c]=i(s,this.half);t.beginPath(),t.moveTo(r,o),t.lineTo(a,c),t.stroke();let[l,h]=i(-this.half,s),[f,u]=i(this.half,s);t.beginPath(),t.moveTo(l,h),t.lineTo(f,u),t.stroke()}if(t.fillStyle="#5b6b7b",t.font="11px sans-serif",t.fillText(`1 m grid · ${2*this.half} m across`,8,e.h-8),this.scan){t.fillStyle="#f2c94c";for(let s=0;s<this.scan.length;s+=2){let[r,o]=i(this.scan[s],this.scan[s+1]);t.fillRect(r-1,o-1,2,2)}}if(this.goal){let[s,r]=i(this.goal.x,this.goal.y);t.strokeStyle="#6fcf97",t.lineWidth=2,t.beginPath(),t.arc(s,r,9,0,Math.PI*2),t.stroke(),t.beginPath(),t.moveTo(s-13,r),t.lineTo(s+13,r),t.moveTo(s,r-13),t.lineTo(s,r+13),t.stroke()}for(let s of this.robots.values()){let r=s.online?s.colour:"#56606a";if(s.trail.length>1&&(t.strokeStyle=r,t.globalAlpha=.55,t.lineWidth=2,t.beginPath(),s.trail.forEach((l,h)=>{let[f,u]=i(l.x,l.y);h===0?t.moveTo(f,u):t.lineTo(f,u)}),t.stroke(),t.globalAlpha=1),!s.pose)continue;let[o,a]=i(s.pose.x,s.pose.y),c=Math.max(9,e.scale*.45);t.save(),t.translate(o,a),t.rotate(-s.pose.yaw),t.fillStyle=r,t.strokeStyle=s.name===this.selected?"#ffffff":"#0b1016",t.lineWidth=2,t.beginPath(),t.moveTo(c,0),t.lineTo(-c*.7,c*.6),t.lineTo(-c*.4,0),t.lineTo(-c*.7,-c*.6),t.closePath(),t.fill(),t.stroke(),t.restore(),t.fillStyle=s.online?"#e0e6ec":"#7b8690",t.font="12px sans-serif",t.fillText(s.online?s.name:`${s.name} (offline)`,o+c+3,a-c*.5)}}};function vu(n,e){let t=e.filter(r=>r.name.startsWith(`/${n}/`)),i=r=>t.find(o=>o.type===r),s=i("geometry_msgs/msg/PoseStamped")??i("nav_msgs/msg/Odometry")??i("geometry_msgs/msg/PoseWithCovarianceStamped");return s?{topic:s.name,type:s.type}:null}function G_(n,e){let t=0,i=0,s={};for(let r of e)if(r.name.startsWith(`/${n}/`)){t+=r.rate_hz,i+=r.bandwidth_bps;for(let[o,a]of Object.entries(r.drops??{}))a&&(s[o]=(s[o]??0)+a)}return{rate:t,bw:i,drops:s}}function Sp(n,e,t){n.innerHTML="";let i=ye("div","fleet"),s=ye("div","panel mapbox");s.appendChild(ye("h2","","Fleet map"));let r=ye("div","panel side");r.appendChild(ye("h2","","Robots"));let o=ye("div","robotlist");r.appendChild(o),i.append(s,r),n.appendChild(i);let a=new Jr(s);a.onClick=(g,b)=>{let d=null,m=1.2;for(let v of a.robots.values()){if(!v.pose)continue;let C=Math.hypot(v.pose.x-g,v.pose.y-b);C<m&&(d=v.name,m=C)}d&&t(d)};let c=new Map,l=new Map,h=!1;async function f(){let g=[],b=[];try{[{robots:g},{topics:b}]=await Promise.all([Ti("/api/v1/robots"),Ti("/api/v1/topics")])}catch(d){o.textContent=`cannot list robots: ${d.message}`;return}if(!h){g.sort((d,m)=>d.name.localeCompare(m.name,void 0,{numeric:!0})),g.forEach(d=>{l.has(d.name)||l.set(d.name,vp(l.size))});for(let d of g){let m=vu(d.name,b),v=m?.topic;if(d.online&&m&&!c.has(v)){let S=l.get(d.name);c.set(v,e.subscribe(m.topic,P=>{let T=vl(P);T&&(a.setPose(d.name,T,S),Ot.poses[d.name]={...T,at:Date.now()},ci("fleet-pose"))},{type:m.type,throttle_rate:100,queue_length:1,compression:"none"}))}let C=a.robots.get(d.name);C&&C.online!==d.online&&(C.online=d.online,a.invalidate())}u(g,b)}}function u(g,b){o.innerHTML="",g.length===0&&o.appendChild(ye("p","muted","No robots visible to you yet."));for(let d of g){let m=G_(d.name,b),v=ye("div",`robot ${d.online?"online":"offline"}`);v.dataset.robot=d.name;let C=ye("div","robot-head"),S=ye("span","dot");S.style.background=d.online?l.get(d.name):"#56606a",C.append(S,ye("b","",d.name),ye("span",d.online?"badge ok":"badge off",d.online?"online":`offline · gone ${xu(d.last_seen_ms)}`)),v.appendChild(C);let P=ye("dl","kv"),T=(_,R,W="")=>{let O=ye("dt","",_),L=ye("dd","",R);W&&(L.title=W),P.append(O,L)};if(T("last seen",xu(d.last_seen_ms)),d.online){T("RTT",d.rtt_ms!=null?`${mn(d.rtt_ms)} ms`:"–"),T("goodput",Zr(d.link_rate_bps),"what the robot's link delivered (its link report)"),T("msg/s",mn(m.rate),`${Zr(m.bw)} over ${d.topics.length} topics`);let _=Object.entries(m.drops);T("drops",_.length?_.map(([R,W])=>`${R} ${W}`).join(", "):"none"),T("clock offset",d.clock_offset_ms!=null?`${mn(d.clock_offset_ms)} ms`:"–"),T("share",d.share_bps?Zr(d.share_bps):"unlimited","capacity share of the robot's site")}v.appendChild(P),v.addEventListener("click",()=>t(d.name)),o.appendChild(v)}}f();let p=window.setInterval(f,1e3);return()=>{h=!0,clearInterval(p);for(let g of c.values())g();a.destroy()}}var W_="uplot",X_="u-hz",q_="u-vt",Y_="u-title",$_="u-wrap",Z_="u-under",J_="u-over",K_="u-axis",_r="u-off",j_="u-select",Q_="u-cursor-x",ex="u-cursor-y",tx="u-cursor-pt",nx="u-legend",ix="u-live",sx="u-inline",rx="u-series",ox="u-marker",Mp="u-label",ax="u-value",sa="width",ra="height";var bp="bottom",Kr="left",Su="right",Bu="#000",wp=Bu+"0",Mu="mousemove",Ep="mousedown",bu="mouseup",Tp="mouseenter",Ap="mouseleave",Rp="dblclick",lx="resize",cx="scroll",Cp="change",El="dppxchange",ku="--",so=typeof window<"u",Ru=so?document:null,Qr=so?window:null,hx=so?navigator:null,Ut,Sl;function Cu(){let n=devicePixelRatio;Ut!=n&&(Ut=n,Sl&&Iu(Cp,Sl,Cu),Sl=matchMedia(`(min-resolution: ${Ut-.001}dppx) and (max-resolution: ${Ut+.001}dppx)`),xr(Cp,Sl,Cu),Qr.dispatchEvent(new CustomEvent(El)))}function fi(n,e){if(e!=null){let t=n.classList;!t.contains(e)&&t.add(e)}}function Pu(n,e){let t=n.classList;t.contains(e)&&t.remove(e)}function Qt(n,e,t){n.style[e]=t+"px"}function Oi(n,e,t,i){let s=Ru.createElement(n);return e!=null&&fi(s,e),t?.insertBefore(s,i),s}function Ci(n,e){return Oi("div",n,e)}var Pp=new WeakMap;function rs(n,e,t,i,s){let r="translate("+e+"px,"+t+"px)",o=Pp.get(n);r!=o&&(n.style.transform=r,Pp.set(n,r),e<0||t<0||e>i||t>s?fi(n,_r):Pu(n,_r))}var Ip=new WeakMap;function Lp(n,e,t){let i=e+t,s=Ip.get(n);i!=s&&(Ip.set(n,i),n.style.background=e,n.style.borderColor=t)}var Dp=new WeakMap;function Np(n,e,t,i){let s=e+""+t,r=Dp.get(n);s!=r&&(Dp.set(n,s),n.style.height=t+"px",n.style.width=e+"px",n.style.marginLeft=i?-e/2+"px":0,n.style.marginTop=i?-t/2+"px":0)}var zu={passive:!0},ux={...zu,capture:!0};function xr(n,e,t,i){e.addEventListener(n,t,i?ux:zu)}function Iu(n,e,t,i){e.removeEventListener(n,t,zu)}so&&Cu();function Bi(n,e,t,i){let s;t=t||0,i=i||e.length-1;let r=i<=2147483647;for(;i-t>1;)s=r?t+i>>1:di((t+i)/2),e[s]<n?t=s:i=s;return n-e[t]<=e[i]-n?t:i}function lm(n){return(t,i,s)=>{let r=-1,o=-1;for(let a=i;a<=s;a++)if(n(t[a])){r=a;break}for(let a=s;a>=i;a--)if(n(t[a])){o=a;break}return[r,o]}}var cm=n=>n!=null,hm=n=>n!=null&&n>0,Rl=lm(cm),fx=lm(hm);function dx(n,e,t,i=0,s=!1){let r=s?fx:Rl,o=s?hm:cm;[e,t]=r(n,e,t);let a=n[e],c=n[e];if(e>-1)if(i==1)a=n[e],c=n[t];else if(i==-1)a=n[t],c=n[e];else for(let l=e;l<=t;l++){let h=n[l];o(h)&&(h<a?a=h:h>c&&(c=h))}return[a??Yt,c??-Yt]}function Cl(n,e,t,i){let s=Op(n),r=Op(e);n==e&&(s==-1?(n*=t,e/=t):(n/=t,e*=t));let o=t==10?Ms:um,a=s==1?di:Pi,c=r==1?Pi:di,l=a(o(Tn(n))),h=c(o(Tn(e))),f=eo(t,l),u=eo(t,h);return t==10&&(l<0&&(f=$t(f,-l)),h<0&&(u=$t(u,-h))),i||t==2?(n=f*s,e=u*r):(n=mm(n,f),e=Pl(e,u)),[n,e]}function Vu(n,e,t,i){let s=Cl(n,e,t,i);return n==0&&(s[0]=0),e==0&&(s[1]=0),s}var Hu=.1,Up={mode:3,pad:Hu},aa={pad:0,soft:null,mode:0},px={min:aa,max:aa};function Tl(n,e,t,i){return Il(t)?Fp(n,e,t):(aa.pad=t,aa.soft=i?0:null,aa.mode=i?3:0,Fp(n,e,px))}function Dt(n,e){return n??e}function mx(n,e,t){for(e=Dt(e,0),t=Dt(t,n.length-1);e<=t;){if(n[e]!=null)return!0;e++}return!1}function Fp(n,e,t){let i=t.min,s=t.max,r=Dt(i.pad,0),o=Dt(s.pad,0),a=Dt(i.hard,-Yt),c=Dt(s.hard,Yt),l=Dt(i.soft,Yt),h=Dt(s.soft,-Yt),f=Dt(i.mode,0),u=Dt(s.mode,0),p=e-n,g=Ms(p),b=Kn(Tn(n),Tn(e)),d=Ms(b),m=Tn(d-g);(p<1e-24||m>10)&&(p=0,(n==0||e==0)&&(p=1e-24,f==2&&l!=Yt&&(r=0),u==2&&h!=-Yt&&(o=0)));let v=p||b||1e3,C=Ms(v),S=eo(10,di(C)),P=v*(p==0?n==0?.1:1:r),T=$t(mm(n-P,S/10),24),_=n>=l&&(f==1||f==3&&T<=l||f==2&&T>=l)?l:Yt,R=Kn(a,T<_&&n>=_?_:ki(_,T)),W=v*(p==0?e==0?.1:1:o),O=$t(Pl(e+W,S/10),24),L=e<=h&&(u==1||u==3&&O>=h||u==2&&O<=h)?h:-Yt,G=ki(c,O>L&&e<=L?L:Kn(L,O));return R==G&&R==0&&(G=100),[R,G]}var gx=new Intl.NumberFormat(so?hx.language:"en-US"),Gu=n=>gx.format(n),pi=Math,wl=pi.PI,Tn=pi.abs,di=pi.floor,En=pi.round,Pi=pi.ceil,ki=pi.min,Kn=pi.max,eo=pi.pow,Op=pi.sign,Ms=pi.log10,um=pi.log2,_x=(n,e=1)=>pi.sinh(n)*e,wu=(n,e=1)=>pi.asinh(n/e),Yt=1/0;function Bp(n){return(Ms((n^n>>31)-(n>>31))|0)+1}function Lu(n,e,t){return ki(Kn(n,e),t)}function fm(n){return typeof n=="function"}function Tt(n){return fm(n)?n:()=>n}var xx=()=>{},dm=n=>n,pm=(n,e)=>e,yx=n=>null,kp=n=>!0,zp=(n,e)=>n==e,vx=/\.\d*?(?=9{6,}|0{6,})/gm,yr=n=>{if(_m(n)||Xs.has(n))return n;let e=`${n}`,t=e.match(vx);if(t==null)return n;let i=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${yr(s)}e${r}`}return $t(n,i)};function mr(n,e){return yr($t(yr(n/e))*e)}function Pl(n,e){return yr(Pi(yr(n/e))*e)}function mm(n,e){return yr(di(yr(n/e))*e)}function $t(n,e=0){if(_m(n))return n;let t=10**e,i=n*t*(1+Number.EPSILON);return En(i)/t}var Xs=new Map;function gm(n){return((""+n).split(".")[1]||"").length}function ca(n,e,t,i){let s=[],r=i.map(gm);for(let o=e;o<t;o++){let a=Tn(o),c=$t(eo(n,o),a);for(let l=0;l<i.length;l++){let h=n==10?+`${i[l]}e${o}`:i[l]*c,f=(o>=0?0:a)+(o>=r[l]?0:r[l]),u=n==10?h:$t(h,f);s.push(u),Xs.set(u,f)}}return s}var la={},Wu=[],to=[null,null],Ws=Array.isArray,_m=Number.isInteger,Sx=n=>n===void 0;function Vp(n){return typeof n=="string"}function Il(n){let e=!1;if(n!=null){let t=n.constructor;e=t==null||t==Object}return e}function Mx(n){return n!=null&&typeof n=="object"}var bx=Object.getPrototypeOf(Uint8Array),xm="__proto__";function no(n,e=Il){let t;if(Ws(n)){let i=n.find(s=>s!=null);if(Ws(i)||e(i)){t=Array(n.length);for(let s=0;s<n.length;s++)t[s]=no(n[s],e)}else t=n.slice()}else if(n instanceof bx)t=n.slice();else if(e(n)){t={};for(let i in n)i!=xm&&(t[i]=no(n[i],e))}else t=n;return t}function Sn(n){let e=arguments;for(let t=1;t<e.length;t++){let i=e[t];for(let s in i)s!=xm&&(Il(n[s])?Sn(n[s],no(i[s])):n[s]=no(i[s]))}return n}var wx=0,Ex=1,Tx=2;function Ax(n,e,t){for(let i=0,s,r=-1;i<e.length;i++){let o=e[i];if(o>r){for(s=o-1;s>=0&&n[s]==null;)n[s--]=null;for(s=o+1;s<t&&n[s]==null;)n[r=s++]=null}}}function Rx(n,e){if(Ix(n)){let o=n[0].slice();for(let a=1;a<n.length;a++)o.push(...n[a].slice(1));return Lx(o[0])||(o=Px(o)),o}let t=new Set;for(let o=0;o<n.length;o++){let c=n[o][0],l=c.length;for(let h=0;h<l;h++)t.add(c[h])}let i=[Array.from(t).sort((o,a)=>o-a)],s=i[0].length,r=new Map;for(let o=0;o<s;o++)r.set(i[0][o],o);for(let o=0;o<n.length;o++){let a=n[o],c=a[0];for(let l=1;l<a.length;l++){let h=a[l],f=Array(s).fill(void 0),u=e?e[o][l]:Ex,p=[];for(let g=0;g<h.length;g++){let b=h[g],d=r.get(c[g]);b===null?u!=wx&&(f[d]=b,u==Tx&&p.push(d)):f[d]=b}Ax(f,p,s),i.push(f)}}return i}var Cx=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function Px(n){let e=n[0],t=e.length,i=Array(t);for(let r=0;r<i.length;r++)i[r]=r;i.sort((r,o)=>e[r]-e[o]);let s=[];for(let r=0;r<n.length;r++){let o=n[r],a=Array(t);for(let c=0;c<t;c++)a[c]=o[i[c]];s.push(a)}return s}function Ix(n){let e=n[0][0],t=e.length;for(let i=1;i<n.length;i++){let s=n[i][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function Lx(n,e=100){let t=n.length;if(t<=1)return!0;let i=0,s=t-1;for(;i<=s&&n[i]==null;)i++;for(;s>=i&&n[s]==null;)s--;if(s<=i)return!0;let r=Kn(1,di((s-i+1)/e));for(let o=n[i],a=i+r;a<=s;a+=r){let c=n[a];if(c!=null){if(c<=o)return!1;o=c}}return!0}var ym=["January","February","March","April","May","June","July","August","September","October","November","December"],vm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Sm(n){return n.slice(0,3)}var Dx=vm.map(Sm),Nx=ym.map(Sm),Ux={MMMM:ym,MMM:Nx,WWWW:vm,WWW:Dx};function ia(n){return(n<10?"0":"")+n}function Fx(n){return(n<10?"00":n<100?"0":"")+n}var Ox={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,e)=>e.MMMM[n.getMonth()],MMM:(n,e)=>e.MMM[n.getMonth()],MM:n=>ia(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>ia(n.getDate()),D:n=>n.getDate(),WWWW:(n,e)=>e.WWWW[n.getDay()],WWW:(n,e)=>e.WWW[n.getDay()],HH:n=>ia(n.getHours()),H:n=>n.getHours(),h:n=>{let e=n.getHours();return e==0?12:e>12?e-12:e},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>ia(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>ia(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>Fx(n.getMilliseconds())};function Xu(n,e){e=e||Ux;let t=[],i=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=i.exec(n);)t.push(s[0][0]=="{"?Ox[s[1]]:s[0]);return r=>{let o="";for(let a=0;a<t.length;a++)o+=typeof t[a]=="string"?t[a]:t[a](r,e);return o}}var Bx=new Intl.DateTimeFormat().resolvedOptions().timeZone;function kx(n,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+n+n.getTimezoneOffset()*6e4):e==Bx?t=n:(t=new Date(n.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(n.getMilliseconds())),t}var Mm=n=>n%1==0,Al=[1,2,2.5,5],zx=ca(10,-32,0,Al),bm=ca(10,0,32,Al),Vx=bm.filter(Mm),gr=zx.concat(bm),qu=`
`,wm="{YYYY}",Hp=qu+wm,Em="{M}/{D}",oa=qu+Em,Ml=oa+"/{YY}",Tm="{aa}",Hx="{h}:{mm}",jr=Hx+Tm,Gp=qu+jr,Wp=":{ss}",Bt=null;function Am(n){let e=n*1e3,t=e*60,i=t*60,s=i*24,r=s*30,o=s*365,c=(n==1?ca(10,0,3,Al).filter(Mm):ca(10,-3,0,Al)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,i,i*2,i*3,i*4,i*6,i*8,i*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,o,o*2,o*5,o*10,o*25,o*50,o*100]),l=[[o,wm,Bt,Bt,Bt,Bt,Bt,Bt,1],[s*28,"{MMM}",Hp,Bt,Bt,Bt,Bt,Bt,1],[s,Em,Hp,Bt,Bt,Bt,Bt,Bt,1],[i,"{h}"+Tm,Ml,Bt,oa,Bt,Bt,Bt,1],[t,jr,Ml,Bt,oa,Bt,Bt,Bt,1],[e,Wp,Ml+" "+jr,Bt,oa+" "+jr,Bt,Gp,Bt,1],[n,Wp+".{fff}",Ml+" "+jr,Bt,oa+" "+jr,Bt,Gp,Bt,1]];function h(f){return(u,p,g,b,d,m)=>{let v=[],C=d>=o,S=d>=r&&d<o,P=f(g),T=$t(P*n,3),_=Eu(P.getFullYear(),C?0:P.getMonth(),S||C?1:P.getDate()),R=$t(_*n,3);if(S||C){let W=S?d/r:0,O=C?d/o:0,L=T==R?T:$t(Eu(_.getFullYear()+O,_.getMonth()+W,1)*n,3),G=new Date(En(L/n)),X=G.getFullYear(),y=G.getMonth();for(let U=0;L<=b;U++){let D=Eu(X+O*U,y+W*U,1),A=D-f($t(D*n,3));L=$t((+D+A)*n,3),L<=b&&v.push(L)}}else{let W=d>=s?s:d,O=di(g)-di(T),L=R+O+Pl(T-R,W);v.push(L);let G=f(L),X=G.getHours()+G.getMinutes()/t+G.getSeconds()/i,y=d/i,U=u.axes[p]._space,D=m/U;for(;L=$t(L+d,n==1?0:3),!(L>b);)if(y>1){let A=di($t(X+y,6))%24,H=f(L).getHours()-A;H>1&&(H=-1),L-=H*i,X=(X+y)%24;let $=v[v.length-1];$t((L-$)/d,3)*D>=.7&&v.push(L)}else v.push(L)}return v}}return[c,l,h]}var[Gx,Wx,Xx]=Am(1),[qx,Yx,$x]=Am(.001);ca(2,-53,53,[1]);function Xp(n,e){return n.map(t=>t.map((i,s)=>s==0||s==8||i==null?i:e(s==1||t[8]==0?i:t[1]+i)))}function qp(n,e){return(t,i,s,r,o)=>{let a=e.find(g=>o>=g[0])||e[e.length-1],c,l,h,f,u,p;return i.map(g=>{let b=n(g),d=b.getFullYear(),m=b.getMonth(),v=b.getDate(),C=b.getHours(),S=b.getMinutes(),P=b.getSeconds(),T=d!=c&&a[2]||m!=l&&a[3]||v!=h&&a[4]||C!=f&&a[5]||S!=u&&a[6]||P!=p&&a[7]||a[1];return c=d,l=m,h=v,f=C,u=S,p=P,T(b)})}}function Zx(n,e){let t=Xu(e);return(i,s,r,o,a)=>s.map(c=>t(n(c)))}function Eu(n,e,t){return new Date(n,e,t)}function Yp(n,e){return e(n)}var Jx="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function $p(n,e){return(t,i,s,r)=>r==null?ku:e(n(i))}function Kx(n,e){let t=n.series[e];return t.width?t.stroke(n,e):t.points.width?t.points.stroke(n,e):null}function jx(n,e){return n.series[e].fill(n,e)}var Qx={show:!0,live:!0,isolate:!1,mount:xx,markers:{show:!0,width:2,stroke:Kx,fill:jx,dash:"solid"},idx:null,idxs:null,values:[]};function ey(n,e){let t=n.cursor.points,i=Ci(),s=t.size(n,e);Qt(i,sa,s),Qt(i,ra,s);let r=s/-2;Qt(i,"marginLeft",r),Qt(i,"marginTop",r);let o=t.width(n,e,s);return o&&Qt(i,"borderWidth",o),i}function ty(n,e){let t=n.series[e].points;return t._fill||t._stroke}function ny(n,e){let t=n.series[e].points;return t._stroke||t._fill}function iy(n,e){return n.series[e].points.size}var Tu=[0,0];function sy(n,e,t){return Tu[0]=e,Tu[1]=t,Tu}function bl(n,e,t,i=!0){return s=>{s.button==0&&(!i||s.target==e)&&t(s)}}function Au(n,e,t,i=!0){return s=>{(!i||s.target==e)&&t(s)}}var ry={show:!0,x:!0,y:!0,lock:!1,move:sy,points:{one:!1,show:ey,size:iy,width:0,stroke:ny,fill:ty},bind:{mousedown:bl,mouseup:bl,click:bl,dblclick:bl,mousemove:Au,mouseleave:Au,mouseenter:Au},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,e,t,i,s)=>i-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Rm={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Yu=Sn({},Rm,{filter:pm}),Cm=Sn({},Yu,{size:10}),Pm=Sn({},Rm,{show:!1}),$u='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Im="bold "+$u,Lm=1.5,Zp={show:!0,scale:"x",stroke:Bu,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Im,side:2,grid:Yu,ticks:Cm,border:Pm,font:$u,lineGap:Lm,rotate:0},oy="Value",ay="Time",Jp={show:!0,scale:"x",auto:!1,sorted:1,min:Yt,max:-Yt,idxs:[]};function ly(n,e,t,i,s){return e.map(r=>r==null?"":Gu(r))}function cy(n,e,t,i,s,r,o){let a=[],c=Xs.get(s)||0;t=o?t:$t(Pl(t,s),c);for(let l=t;l<=i;l=$t(l+s,c))a.push(Object.is(l,-0)?0:l);return a}function Du(n,e,t,i,s,r,o){let a=[],c=n.scales[n.axes[e].scale].log,l=c==10?Ms:um,h=di(l(t));s=eo(c,h),c==10&&(s=gr[Bi(s,gr)]);let f=t,u=s*c;c==10&&(u=gr[Bi(u,gr)]);do a.push(f),f=f+s,c==10&&!Xs.has(f)&&(f=$t(f,Xs.get(s))),f>=u&&(s=f,u=s*c,c==10&&(u=gr[Bi(u,gr)]));while(f<=i);return a}function hy(n,e,t,i,s,r,o){let c=n.scales[n.axes[e].scale].asinh,l=i>c?Du(n,e,Kn(c,t),i,s):[c],h=i>=0&&t<=0?[0]:[];return(t<-c?Du(n,e,Kn(c,-i),-t,s):[c]).reverse().map(u=>-u).concat(h,l)}var Dm=/./,uy=/[12357]/,fy=/[125]/,Kp=/1/,Nu=(n,e,t,i)=>n.map((s,r)=>e==4&&s==0||r%i==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function dy(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=n.scales[o],c=n.valToPos,l=r._space,h=c(10,o),f=c(9,o)-h>=l?Dm:c(7,o)-h>=l?uy:c(5,o)-h>=l?fy:Kp;if(f==Kp){let u=Tn(c(1,o)-h);if(u<l)return Nu(e.slice().reverse(),a.distr,f,Pi(l/u)).reverse()}return Nu(e,a.distr,f,1)}function py(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=r._space,c=n.valToPos,l=Tn(c(1,o)-c(2,o));return l<a?Nu(e.slice().reverse(),3,Dm,Pi(a/l)).reverse():e}function my(n,e,t,i){return i==null?ku:e==null?"":Gu(e)}var jp={show:!0,scale:"y",stroke:Bu,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Im,side:3,grid:Yu,ticks:Cm,border:Pm,font:$u,lineGap:Lm,rotate:0};function gy(n,e){let t=3+(n||1)*2;return $t(t*e,3)}function _y(n,e){let{scale:t,idxs:i}=n.series[0],s=n._data[0],r=n.valToPos(s[i[0]],t,!0),o=n.valToPos(s[i[1]],t,!0),a=Tn(o-r),c=n.series[e],l=a/(c.points.space*Ut);return i[1]-i[0]<=l}var Qp={scale:null,auto:!0,sorted:0,min:Yt,max:-Yt},Nm=(n,e,t,i,s)=>s,em={show:!0,auto:!0,sorted:0,gaps:Nm,alpha:1,facets:[Sn({},Qp,{scale:"x"}),Sn({},Qp,{scale:"y"})]},tm={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:Nm,alpha:1,points:{show:_y,filter:null},values:null,min:Yt,max:-Yt,idxs:[],path:null,clip:null};function xy(n,e,t,i,s){return t/10}var Um={time:!0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},yy=Sn({},Um,{time:!1,ori:1}),nm={};function Fm(n,e){let t=nm[n];return t||(t={key:n,plots:[],sub(i){t.plots.push(i)},unsub(i){t.plots=t.plots.filter(s=>s!=i)},pub(i,s,r,o,a,c,l){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(i,s,r,o,a,c,l)}},n!=null&&(nm[n]=t)),t}var io=1,Uu=2;function vr(n,e,t){let i=n.mode,s=n.series[e],r=i==2?n._data[e]:n._data,o=n.scales,a=n.bbox,c=r[0],l=i==2?r[1]:r[e],h=i==2?o[s.facets[0].scale]:o[n.series[0].scale],f=i==2?o[s.facets[1].scale]:o[s.scale],u=a.left,p=a.top,g=a.width,b=a.height,d=n.valToPosH,m=n.valToPosV;return h.ori==0?t(s,c,l,h,f,d,m,u,p,g,b,Dl,ro,Ul,Bm,zm):t(s,c,l,h,f,m,d,p,u,b,g,Nl,oo,Ku,km,Vm)}function Zu(n,e){let t=0,i=0,s=Dt(n.bands,Wu);for(let r=0;r<s.length;r++){let o=s[r];o.series[0]==e?t=o.dir:o.series[1]==e&&(o.dir==1?i|=1:i|=2)}return[t,i==1?-1:i==2?1:i==3?2:0]}function vy(n,e,t,i,s){let r=n.mode,o=n.series[e],a=r==2?o.facets[1].scale:o.scale,c=n.scales[a];return s==-1?c.min:s==1?c.max:c.distr==3?c.dir==1?c.min:c.max:0}function bs(n,e,t,i,s,r){return vr(n,e,(o,a,c,l,h,f,u,p,g,b,d)=>{let m=o.pxRound,v=l.dir*(l.ori==0?1:-1),C=l.ori==0?ro:oo,S,P;v==1?(S=t,P=i):(S=i,P=t);let T=m(f(a[S],l,b,p)),_=m(u(c[S],h,d,g)),R=m(f(a[P],l,b,p)),W=m(u(r==1?h.max:h.min,h,d,g)),O=new Path2D(s);return C(O,R,W),C(O,T,W),C(O,T,_),O})}function Ll(n,e,t,i,s,r){let o=null;if(n.length>0){o=new Path2D;let a=e==0?Ul:Ku,c=t;for(let f=0;f<n.length;f++){let u=n[f];if(u[1]>u[0]){let p=u[0]-c;p>0&&a(o,c,i,p,i+r),c=u[1]}}let l=t+s-c,h=10;l>0&&a(o,c,i-h/2,l,i+r+h)}return o}function Sy(n,e,t){let i=n[n.length-1];i&&i[0]==e?i[1]=t:n.push([e,t])}function Ju(n,e,t,i,s,r,o){let a=[],c=n.length;for(let l=s==1?t:i;l>=t&&l<=i;l+=s)if(e[l]===null){let f=l,u=l;if(s==1)for(;++l<=i&&e[l]===null;)u=l;else for(;--l>=t&&e[l]===null;)u=l;let p=r(n[f]),g=u==f?p:r(n[u]),b=f-s;p=o<=0&&b>=0&&b<c?r(n[b]):p;let m=u+s;g=o>=0&&m>=0&&m<c?r(n[m]):g,g>=p&&a.push([p,g])}return a}function im(n){return n==0?dm:n==1?En:e=>mr(e,n)}function Om(n){let e=n==0?Dl:Nl,t=n==0?(s,r,o,a,c,l)=>{s.arcTo(r,o,a,c,l)}:(s,r,o,a,c,l)=>{s.arcTo(o,r,c,a,l)},i=n==0?(s,r,o,a,c)=>{s.rect(r,o,a,c)}:(s,r,o,a,c)=>{s.rect(o,r,c,a)};return(s,r,o,a,c,l=0,h=0)=>{l==0&&h==0?i(s,r,o,a,c):(l=ki(l,a/2,c/2),h=ki(h,a/2,c/2),e(s,r+l,o),t(s,r+a,o,r+a,o+c,l),t(s,r+a,o+c,r,o+c,h),t(s,r,o+c,r,o,h),t(s,r,o,r+a,o,l),s.closePath())}}var Dl=(n,e,t)=>{n.moveTo(e,t)},Nl=(n,e,t)=>{n.moveTo(t,e)},ro=(n,e,t)=>{n.lineTo(e,t)},oo=(n,e,t)=>{n.lineTo(t,e)},Ul=Om(0),Ku=Om(1),Bm=(n,e,t,i,s,r)=>{n.arc(e,t,i,s,r)},km=(n,e,t,i,s,r)=>{n.arc(t,e,i,s,r)},zm=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(e,t,i,s,r,o)},Vm=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(t,e,s,i,o,r)};function Hm(n){return(e,t,i,s,r)=>vr(e,t,(o,a,c,l,h,f,u,p,g,b,d)=>{let{pxRound:m,points:v}=o,C,S;l.ori==0?(C=Dl,S=Bm):(C=Nl,S=km);let P=$t(v.width*Ut,3),T=(v.size-v.width)/2*Ut,_=$t(T*2,3),R=new Path2D,W=new Path2D,{left:O,top:L,width:G,height:X}=e.bbox;Ul(W,O-_,L-_,G+_*2,X+_*2);let y=U=>{if(c[U]!=null){let D=m(f(a[U],l,b,p)),A=m(u(c[U],h,d,g));C(R,D+T,A),S(R,D,A,T,0,wl*2)}};if(r)r.forEach(y);else for(let U=i;U<=s;U++)y(U);return{stroke:P>0?R:null,fill:R,clip:W,flags:io|Uu}})}function Gm(n){return(e,t,i,s,r,o)=>{i!=s&&(r!=i&&o!=i&&n(e,t,i),r!=s&&o!=s&&n(e,t,s),n(e,t,o))}}var My=Gm(ro),by=Gm(oo);function Wm(n){let e=Dt(n?.alignGaps,0);return(t,i,s,r)=>vr(t,i,(o,a,c,l,h,f,u,p,g,b,d)=>{[s,r]=Rl(c,s,r);let m=o.pxRound,v=X=>m(f(X,l,b,p)),C=X=>m(u(X,h,d,g)),S,P;l.ori==0?(S=ro,P=My):(S=oo,P=by);let T=l.dir*(l.ori==0?1:-1),_={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:io},R=_.stroke,W=!1;if(r-s>=b*4){let X=oe=>t.posToVal(oe,l.key,!0),y=null,U=null,D,A,z,B=v(a[T==1?s:r]),H=v(a[s]),$=v(a[r]),ne=X(T==1?H+1:$-1);for(let oe=T==1?s:r;oe>=s&&oe<=r;oe+=T){let se=a[oe],me=(T==1?se<ne:se>ne)?B:v(se),Ee=c[oe];me==B?Ee!=null?(A=Ee,y==null?(S(R,me,C(A)),D=y=U=A):A<y?y=A:A>U&&(U=A)):Ee===null&&(W=!0):(y!=null&&P(R,B,C(y),C(U),C(D),C(A)),Ee!=null?(A=Ee,S(R,me,C(A)),y=U=D=A):(y=U=null,Ee===null&&(W=!0)),B=me,ne=X(B+T))}y!=null&&y!=U&&z!=B&&P(R,B,C(y),C(U),C(D),C(A))}else for(let X=T==1?s:r;X>=s&&X<=r;X+=T){let y=c[X];y===null?W=!0:y!=null&&S(R,v(a[X]),C(y))}let[L,G]=Zu(t,i);if(o.fill!=null||L!=0){let X=_.fill=new Path2D(R),y=o.fillTo(t,i,o.min,o.max,L),U=C(y),D=v(a[s]),A=v(a[r]);T==-1&&([A,D]=[D,A]),S(X,A,U),S(X,D,U)}if(!o.spanGaps){let X=[];W&&X.push(...Ju(a,c,s,r,T,v,e)),_.gaps=X=o.gaps(t,i,s,r,X),_.clip=Ll(X,l.ori,p,g,b,d)}return G!=0&&(_.band=G==2?[bs(t,i,s,r,R,-1),bs(t,i,s,r,R,1)]:bs(t,i,s,r,R,G)),_})}function wy(n){let e=Dt(n.align,1),t=Dt(n.ascDesc,!1),i=Dt(n.alignGaps,0),s=Dt(n.extend,!1);return(r,o,a,c)=>vr(r,o,(l,h,f,u,p,g,b,d,m,v,C)=>{[a,c]=Rl(f,a,c);let S=l.pxRound,{left:P,width:T}=r.bbox,_=H=>S(g(H,u,v,d)),R=H=>S(b(H,p,C,m)),W=u.ori==0?ro:oo,O={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:io},L=O.stroke,G=u.dir*(u.ori==0?1:-1),X=R(f[G==1?a:c]),y=_(h[G==1?a:c]),U=y,D=y;s&&e==-1&&(D=P,W(L,D,X)),W(L,y,X);for(let H=G==1?a:c;H>=a&&H<=c;H+=G){let $=f[H];if($==null)continue;let ne=_(h[H]),oe=R($);e==1?W(L,ne,X):W(L,U,oe),W(L,ne,oe),X=oe,U=ne}let A=U;s&&e==1&&(A=P+T,W(L,A,X));let[z,B]=Zu(r,o);if(l.fill!=null||z!=0){let H=O.fill=new Path2D(L),$=l.fillTo(r,o,l.min,l.max,z),ne=R($);W(H,A,ne),W(H,D,ne)}if(!l.spanGaps){let H=[];H.push(...Ju(h,f,a,c,G,_,i));let $=l.width*Ut/2,ne=t||e==1?$:-$,oe=t||e==-1?-$:$;H.forEach(se=>{se[0]+=ne,se[1]+=oe}),O.gaps=H=l.gaps(r,o,a,c,H),O.clip=Ll(H,u.ori,d,m,v,C)}return B!=0&&(O.band=B==2?[bs(r,o,a,c,L,-1),bs(r,o,a,c,L,1)]:bs(r,o,a,c,L,B)),O})}function sm(n,e,t,i,s,r,o=Yt){if(n.length>1){let a=null;for(let c=0,l=1/0;c<n.length;c++)if(e[c]!==void 0){if(a!=null){let h=Tn(n[c]-n[a]);h<l&&(l=h,o=Tn(t(n[c],i,s,r)-t(n[a],i,s,r)))}a=c}}return o}function Ey(n){n=n||la;let e=Dt(n.size,[.6,Yt,1]),t=n.align||0,i=n.gap||0,s=n.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;let r=Tt(s),o=1-e[0],a=Dt(e[1],Yt),c=Dt(e[2],1),l=Dt(n.disp,la),h=Dt(n.each,p=>{}),{fill:f,stroke:u}=l;return(p,g,b,d)=>vr(p,g,(m,v,C,S,P,T,_,R,W,O,L)=>{let G=m.pxRound,X=t,y=i*Ut,U=a*Ut,D=c*Ut,A,z;S.ori==0?[A,z]=r(p,g):[z,A]=r(p,g);let B=S.dir*(S.ori==0?1:-1),H=S.ori==0?Ul:Ku,$=S.ori==0?h:(De,tt,ut,Ae,Xt,$e,Qe)=>{h(De,tt,ut,Xt,Ae,Qe,$e)},ne=Dt(p.bands,Wu).find(De=>De.series[0]==g),oe=ne!=null?ne.dir:0,se=m.fillTo(p,g,m.min,m.max,oe),_e=G(_(se,P,L,W)),me,Ee,Se,Ze=O,rt=G(m.width*Ut),Ye=!1,Ie=null,Ue=null,Ve=null,yt=null;f!=null&&(rt==0||u!=null)&&(Ye=!0,Ie=f.values(p,g,b,d),Ue=new Map,new Set(Ie).forEach(De=>{De!=null&&Ue.set(De,new Path2D)}),rt>0&&(Ve=u.values(p,g,b,d),yt=new Map,new Set(Ve).forEach(De=>{De!=null&&yt.set(De,new Path2D)})));let{x0:Pt,size:zt}=l;if(Pt!=null&&zt!=null){X=1,v=Pt.values(p,g,b,d),Pt.unit==2&&(v=v.map(ut=>p.posToVal(R+ut*O,S.key,!0)));let De=zt.values(p,g,b,d);zt.unit==2?Ee=De[0]*O:Ee=T(De[0],S,O,R)-T(0,S,O,R),Ze=sm(v,C,T,S,O,R,Ze),Se=Ze-Ee+y}else Ze=sm(v,C,T,S,O,R,Ze),Se=Ze*o+y,Ee=Ze-Se;Se<1&&(Se=0),rt>=Ee/2&&(rt=0),Se<5&&(G=dm);let ct=Se>0,It=Ze-Se-(ct?rt:0);Ee=G(Lu(It,D,U)),me=(X==0?Ee/2:X==B?0:Ee)-X*B*((X==0?y/2:0)+(ct?rt/2:0));let je={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},dt=Ye?null:new Path2D,mt=null;if(ne!=null)mt=p.data[ne.series[1]];else{let{y0:De,y1:tt}=l;De!=null&&tt!=null&&(C=tt.values(p,g,b,d),mt=De.values(p,g,b,d))}let bt=A*Ee,k=z*Ee;for(let De=B==1?b:d;De>=b&&De<=d;De+=B){let tt=C[De];if(tt==null)continue;if(mt!=null){let J=mt[De]??0;if(tt-J==0)continue;_e=_(J,P,L,W)}let ut=S.distr!=2||l!=null?v[De]:De,Ae=T(ut,S,O,R),Xt=_(Dt(tt,se),P,L,W),$e=G(Ae-me),Qe=G(Kn(Xt,_e)),I=G(ki(Xt,_e)),M=Qe-I;if(tt!=null){let J=tt<0?k:bt,pe=tt<0?bt:k;Ye?(rt>0&&Ve[De]!=null&&H(yt.get(Ve[De]),$e,I+di(rt/2),Ee,Kn(0,M-rt),J,pe),Ie[De]!=null&&H(Ue.get(Ie[De]),$e,I+di(rt/2),Ee,Kn(0,M-rt),J,pe)):H(dt,$e,I+di(rt/2),Ee,Kn(0,M-rt),J,pe),$(p,g,De,$e-rt/2,I,Ee+rt,M)}}return rt>0?je.stroke=Ye?yt:dt:Ye||(je._fill=m.width==0?m._fill:m._stroke??m._fill,je.width=0),je.fill=Ye?Ue:dt,je})}function Ty(n,e){let t=Dt(e?.alignGaps,0);return(i,s,r,o)=>vr(i,s,(a,c,l,h,f,u,p,g,b,d,m)=>{[r,o]=Rl(l,r,o);let v=a.pxRound,C=A=>v(u(A,h,d,g)),S=A=>v(p(A,f,m,b)),P,T,_;h.ori==0?(P=Dl,_=ro,T=zm):(P=Nl,_=oo,T=Vm);let R=h.dir*(h.ori==0?1:-1),W=C(c[R==1?r:o]),O=W,L=[],G=[];for(let A=R==1?r:o;A>=r&&A<=o;A+=R)if(l[A]!=null){let B=c[A],H=C(B);L.push(O=H),G.push(S(l[A]))}let X={stroke:n(L,G,P,_,T,v),fill:null,clip:null,band:null,gaps:null,flags:io},y=X.stroke,[U,D]=Zu(i,s);if(a.fill!=null||U!=0){let A=X.fill=new Path2D(y),z=a.fillTo(i,s,a.min,a.max,U),B=S(z);_(A,O,B),_(A,W,B)}if(!a.spanGaps){let A=[];A.push(...Ju(c,l,r,o,R,C,t)),X.gaps=A=a.gaps(i,s,r,o,A),X.clip=Ll(A,h.ori,g,b,d,m)}return D!=0&&(X.band=D==2?[bs(i,s,r,o,y,-1),bs(i,s,r,o,y,1)]:bs(i,s,r,o,y,D)),X})}function Ay(n){return Ty(Ry,n)}function Ry(n,e,t,i,s,r){let o=n.length;if(o<2)return null;let a=new Path2D;if(t(a,n[0],e[0]),o==2)i(a,n[1],e[1]);else{let c=Array(o),l=Array(o-1),h=Array(o-1),f=Array(o-1);for(let u=0;u<o-1;u++)h[u]=e[u+1]-e[u],f[u]=n[u+1]-n[u],l[u]=h[u]/f[u];c[0]=l[0];for(let u=1;u<o-1;u++)l[u]===0||l[u-1]===0||l[u-1]>0!=l[u]>0?c[u]=0:(c[u]=3*(f[u-1]+f[u])/((2*f[u]+f[u-1])/l[u-1]+(f[u]+2*f[u-1])/l[u]),isFinite(c[u])||(c[u]=0));c[o-1]=l[o-2];for(let u=0;u<o-1;u++)s(a,n[u]+f[u]/3,e[u]+c[u]*f[u]/3,n[u+1]-f[u]/3,e[u+1]-c[u+1]*f[u]/3,n[u+1],e[u+1])}return a}var Fu=new Set;function rm(){for(let n of Fu)n.syncRect(!0)}so&&(xr(lx,Qr,rm),xr(cx,Qr,rm,!0),xr(El,Qr,()=>{Un.pxRatio=Ut}));var Cy=Wm(),Py=Hm();function om(n,e,t,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((r,o)=>Ou(r,o,e,t))}function Iy(n,e){return n.map((t,i)=>i==0?{}:Sn({},e,t))}function Ou(n,e,t,i){return Sn({},e==0?t:i,n)}function Xm(n,e,t){return e==null?to:[e,t]}var Ly=Xm;function Dy(n,e,t){return e==null?to:Tl(e,t,Hu,!0)}function qm(n,e,t,i){return e==null?to:Cl(e,t,n.scales[i].log,!1)}var Ny=qm;function Ym(n,e,t,i){return e==null?to:Vu(e,t,n.scales[i].log,!1)}var Uy=Ym;function Fy(n,e,t,i,s){let r=Kn(Bp(n),Bp(e)),o=e-n,a=Bi(s/i*o,t);do{let c=t[a],l=i*c/o;if(l>=s&&r+(c<5?Xs.get(c):0)<=17)return[c,l]}while(++a<t.length);return[0,0]}function am(n){let e,t;return n=n.replace(/(\d+)px/,(i,s)=>(e=En((t=+s)*Ut))+"px"),[n,e,t]}function Oy(n){n.show&&[n.font,n.labelFont].forEach(e=>{let t=$t(e[2]*Ut,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Un(n,e,t){let i={mode:Dt(n.mode,1)},s=i.mode;function r(x,w,N,F){let Z=w.valToPct(x);return F+N*(w.dir==-1?1-Z:Z)}function o(x,w,N,F){let Z=w.valToPct(x);return F+N*(w.dir==-1?Z:1-Z)}function a(x,w,N,F){return w.ori==0?r(x,w,N,F):o(x,w,N,F)}i.valToPosH=r,i.valToPosV=o;let c=!1;i.status=0;let l=i.root=Ci(W_);if(n.id!=null&&(l.id=n.id),fi(l,n.class),n.title){let x=Ci(Y_,l);x.textContent=n.title}let h=Oi("canvas"),f=i.ctx=h.getContext("2d"),u=Ci($_,l);xr("click",u,x=>{x.target===g&&(Jt!=zr||tn!=Vr)&&kn.click(i,x)},!0);let p=i.under=Ci(Z_,u);u.appendChild(h);let g=i.over=Ci(J_,u);n=no(n);let b=+Dt(n.pxAlign,1),d=im(b);(n.plugins||[]).forEach(x=>{x.opts&&(n=x.opts(i,n)||n)});let m=n.ms||.001,v=i.series=s==1?om(n.series||[],Jp,tm,!1):Iy(n.series||[null],em),C=i.axes=om(n.axes||[],Zp,jp,!0),S=i.scales={},P=i.bands=n.bands||[];P.forEach(x=>{x.fill=Tt(x.fill||null),x.dir=Dt(x.dir,-1)});let T=s==2?v[1].facets[0].scale:v[0].scale,_={axes:_s,series:St},R=(n.drawOrder||["axes","series"]).map(x=>_[x]);function W(x){let w=x.distr==3?N=>Ms(N>0?N:x.clamp(i,N,x.min,x.max,x.key)):x.distr==4?N=>wu(N,x.asinh):x.distr==100?N=>x.fwd(N):N=>N;return N=>{let F=w(N),{_min:Z,_max:te}=x,fe=te-Z;return(F-Z)/fe}}function O(x){let w=S[x];if(w==null){let N=(n.scales||la)[x]||la;if(N.from!=null){O(N.from);let F=Sn({},S[N.from],N,{key:x});F.valToPct=W(F),S[x]=F}else{w=S[x]=Sn({},x==T?Um:yy,N),w.key=x;let F=w.time,Z=w.range,te=Ws(Z);if((x!=T||s==2&&!F)&&(te&&(Z[0]==null||Z[1]==null)&&(Z={min:Z[0]==null?Up:{mode:1,hard:Z[0],soft:Z[0]},max:Z[1]==null?Up:{mode:1,hard:Z[1],soft:Z[1]}},te=!1),!te&&Il(Z))){let fe=Z;Z=(ge,we,Be)=>we==null?to:Tl(we,Be,fe)}w.range=Tt(Z||(F?Ly:x==T?w.distr==3?Ny:w.distr==4?Uy:Xm:w.distr==3?qm:w.distr==4?Ym:Dy)),w.auto=Tt(te?!1:w.auto),w.clamp=Tt(w.clamp||xy),w._min=w._max=null,w.valToPct=W(w)}}}O("x"),O("y"),s==1&&v.forEach(x=>{O(x.scale)}),C.forEach(x=>{O(x.scale)});for(let x in n.scales)O(x);let L=S[T],G=L.distr,X,y;L.ori==0?(fi(l,X_),X=r,y=o):(fi(l,q_),X=o,y=r);let U={};for(let x in S){let w=S[x];(w.min!=null||w.max!=null)&&(U[x]={min:w.min,max:w.max},w.min=w.max=null)}let D=n.tzDate||(x=>new Date(En(x/m))),A=n.fmtDate||Xu,z=m==1?Xx(D):$x(D),B=qp(D,Xp(m==1?Wx:Yx,A)),H=$p(D,Yp(Jx,A)),$=[],ne=i.legend=Sn({},Qx,n.legend),oe=i.cursor=Sn({},ry,{drag:{y:s==2}},n.cursor),se=ne.show,_e=oe.show,me=ne.markers;ne.idxs=$,me.width=Tt(me.width),me.dash=Tt(me.dash),me.stroke=Tt(me.stroke),me.fill=Tt(me.fill);let Ee,Se,Ze,rt=[],Ye=[],Ie,Ue=!1,Ve={};if(ne.live){let x=v[1]?v[1].values:null;Ue=x!=null,Ie=Ue?x(i,1,0):{_:0};for(let w in Ie)Ve[w]=ku}if(se)if(Ee=Oi("table",nx,l),Ze=Oi("tbody",null,Ee),ne.mount(i,Ee),Ue){Se=Oi("thead",null,Ee,Ze);let x=Oi("tr",null,Se);Oi("th",null,x);for(var yt in Ie)Oi("th",Mp,x).textContent=yt}else fi(Ee,sx),ne.live&&fi(Ee,ix);let Pt={show:!0},zt={show:!1};function ct(x,w){if(w==0&&(Ue||!ne.live||s==2))return to;let N=[],F=Oi("tr",rx,Ze,Ze.childNodes[w]);fi(F,x.class),x.show||fi(F,_r);let Z=Oi("th",null,F);if(me.show){let ge=Ci(ox,Z);if(w>0){let we=me.width(i,w);we&&(ge.style.border=we+"px "+me.dash(i,w)+" "+me.stroke(i,w)),ge.style.background=me.fill(i,w)}}let te=Ci(Mp,Z);x.label instanceof HTMLElement?te.appendChild(x.label):te.textContent=x.label,w>0&&(me.show||(te.style.color=x.width>0?me.stroke(i,w):me.fill(i,w)),je("click",Z,ge=>{if(oe._lock)return;it(ge);let we=v.indexOf(x);if((ge.ctrlKey||ge.metaKey)!=ne.isolate){let Be=v.some((ke,Ge)=>Ge>0&&Ge!=we&&ke.show);v.forEach((ke,Ge)=>{Ge>0&&ji(Ge,Be?Ge==we?Pt:zt:Pt,!0,yn.setSeries)})}else ji(we,{show:!x.show},!0,yn.setSeries)},!1),st&&je(Tp,Z,ge=>{oe._lock||(it(ge),ji(v.indexOf(x),Gr,!0,yn.setSeries))},!1));for(var fe in Ie){let ge=Oi("td",ax,F);ge.textContent="--",N.push(ge)}return[F,N]}let It=new Map;function je(x,w,N,F=!0){let Z=It.get(w)||{},te=oe.bind[x](i,w,N,F);te&&(xr(x,w,Z[x]=te),It.set(w,Z))}function dt(x,w,N){let F=It.get(w)||{};for(let Z in F)(x==null||Z==x)&&(Iu(Z,w,F[Z]),delete F[Z]);x==null&&It.delete(w)}let mt=0,bt=0,k=0,De=0,tt=0,ut=0,Ae=tt,Xt=ut,$e=k,Qe=De,I=0,M=0,J=0,pe=0;i.bbox={};let ue=!1,Me=!1,be=!1,ae=!1,ce=!1,xe=!1;function V(x,w,N){(N||x!=i.width||w!=i.height)&&he(x,w),gt(!1),be=!0,Me=!0,zn()}function he(x,w){i.width=mt=k=x,i.height=bt=De=w,tt=ut=0,Te(),Je();let N=i.bbox;I=N.left=mr(tt*Ut,.5),M=N.top=mr(ut*Ut,.5),J=N.width=mr(k*Ut,.5),pe=N.height=mr(De*Ut,.5)}let le=3;function Re(){let x=!1,w=0;for(;!x;){w++;let N=Or(w),F=Ki(w);x=w==le||N&&F,x||(he(i.width,i.height),Me=!0)}}function ve({width:x,height:w}){V(x,w)}i.setSize=ve;function Te(){let x=!1,w=!1,N=!1,F=!1;C.forEach((Z,te)=>{if(Z.show&&Z._show){let{side:fe,_size:ge}=Z,we=fe%2,Be=Z.label!=null?Z.labelSize:0,ke=ge+Be;ke>0&&(we?(k-=ke,fe==3?(tt+=ke,F=!0):N=!0):(De-=ke,fe==0?(ut+=ke,x=!0):w=!0))}}),Zi[0]=x,Zi[1]=N,Zi[2]=w,Zi[3]=F,k-=Di[1]+Di[3],tt+=Di[3],De-=Di[2]+Di[0],ut+=Di[0]}function Je(){let x=tt+k,w=ut+De,N=tt,F=ut;function Z(te,fe){switch(te){case 1:return x+=fe,x-fe;case 2:return w+=fe,w-fe;case 3:return N-=fe,N+fe;case 0:return F-=fe,F+fe}}C.forEach((te,fe)=>{if(te.show&&te._show){let ge=te.side;te._pos=Z(ge,te._size),te.label!=null&&(te._lpos=Z(ge,te.labelSize))}})}if(oe.dataIdx==null){let x=oe.hover,w=x.skip=new Set(x.skip??[]);w.add(void 0);let N=x.prox=Tt(x.prox),F=x.bias??=0;oe.dataIdx=(Z,te,fe,ge)=>{if(te==0)return fe;let we=fe,Be=N(Z,te,fe,ge)??Yt,ke=Be>=0&&Be<Yt,Ge=L.ori==0?k:De,ht=oe.left,Nt=e[0],Lt=e[te];if(w.has(Lt[fe])){we=null;let wt=null,nt=null,Ke;if(F==0||F==-1)for(Ke=fe;wt==null&&Ke-- >0;)w.has(Lt[Ke])||(wt=Ke);if(F==0||F==1)for(Ke=fe;nt==null&&Ke++<Lt.length;)w.has(Lt[Ke])||(nt=Ke);if(wt!=null||nt!=null)if(ke){let jt=wt==null?-1/0:X(Nt[wt],L,Ge,0),ln=nt==null?1/0:X(Nt[nt],L,Ge,0),Dn=ht-jt,Wt=ln-ht;Dn<=Wt?Dn<=Be&&(we=wt):Wt<=Be&&(we=nt)}else we=nt==null?wt:wt==null?nt:fe-wt<=nt-fe?wt:nt}else ke&&Tn(ht-X(Nt[fe],L,Ge,0))>Be&&(we=null);return we}}let it=x=>{oe.event=x};oe.idxs=$,oe._lock=!1;let de=oe.points;de.show=Tt(de.show),de.size=Tt(de.size),de.stroke=Tt(de.stroke),de.width=Tt(de.width),de.fill=Tt(de.fill);let We=i.focus=Sn({},n.focus||{alpha:.3},oe.focus),st=We.prox>=0,Le=st&&de.one,pt=[],Zt=[],Xn=[];function zo(x,w){let N=de.show(i,w);if(N instanceof HTMLElement)return fi(N,tx),fi(N,x.class),rs(N,-10,-10,k,De),g.insertBefore(N,pt[w]),N}function Nr(x,w){if(s==1||w>0){let N=s==1&&S[x.scale].time,F=x.value;x.value=N?Vp(F)?$p(D,Yp(F,A)):F||H:F||my,x.label=x.label||(N?ay:oy)}if(Le||w>0){x.width=x.width==null?1:x.width,x.paths=x.paths||Cy||yx,x.fillTo=Tt(x.fillTo||vy),x.pxAlign=+Dt(x.pxAlign,b),x.pxRound=im(x.pxAlign),x.stroke=Tt(x.stroke||null),x.fill=Tt(x.fill||null),x._stroke=x._fill=x._paths=x._focus=null;let N=gy(Kn(1,x.width),1),F=x.points=Sn({},{size:N,width:Kn(1,N*.2),stroke:x.stroke,space:N*2,paths:Py,_stroke:null,_fill:null},x.points);F.show=Tt(F.show),F.filter=Tt(F.filter),F.fill=Tt(F.fill),F.stroke=Tt(F.stroke),F.paths=Tt(F.paths),F.pxAlign=x.pxAlign}if(se){let N=ct(x,w);rt.splice(w,0,N[0]),Ye.splice(w,0,N[1]),ne.values.push(null)}if(_e){$.splice(w,0,null);let N=null;Le?w==0&&(N=zo(x,w)):w>0&&(N=zo(x,w)),pt.splice(w,0,N),Zt.splice(w,0,0),Xn.splice(w,0,0)}Ln("addSeries",w)}function Hh(x,w){w=w??v.length,x=s==1?Ou(x,w,Jp,tm):Ou(x,w,{},em),v.splice(w,0,x),Nr(v[w],w)}i.addSeries=Hh;function Ka(x){if(v.splice(x,1),se){ne.values.splice(x,1),Ye.splice(x,1);let w=rt.splice(x,1)[0];dt(null,w.firstChild),w.remove()}_e&&($.splice(x,1),pt.splice(x,1)[0].remove(),Zt.splice(x,1),Xn.splice(x,1)),Ln("delSeries",x)}i.delSeries=Ka;let Zi=[!1,!1,!1,!1];function ps(x,w){if(x._show=x.show,x.show){let N=x.side%2,F=S[x.scale];F==null&&(x.scale=N?v[1].scale:T,F=S[x.scale]);let Z=F.time;x.size=Tt(x.size),x.space=Tt(x.space),x.rotate=Tt(x.rotate),Ws(x.incrs)&&x.incrs.forEach(fe=>{!Xs.has(fe)&&Xs.set(fe,gm(fe))}),x.incrs=Tt(x.incrs||(F.distr==2?Vx:Z?m==1?Gx:qx:gr)),x.splits=Tt(x.splits||(Z&&F.distr==1?z:F.distr==3?Du:F.distr==4?hy:cy)),x.stroke=Tt(x.stroke),x.grid.stroke=Tt(x.grid.stroke),x.ticks.stroke=Tt(x.ticks.stroke),x.border.stroke=Tt(x.border.stroke);let te=x.values;x.values=Ws(te)&&!Ws(te[0])?Tt(te):Z?Ws(te)?qp(D,Xp(te,A)):Vp(te)?Zx(D,te):te||B:te||ly,x.filter=Tt(x.filter||(F.distr>=3&&F.log==10?dy:F.distr==3&&F.log==2?py:pm)),x.font=am(x.font),x.labelFont=am(x.labelFont),x._size=x.size(i,null,w,0),x._space=x._rotate=x._incrs=x._found=x._splits=x._values=null,x._size>0&&(Zi[w]=!0,x._el=Ci(K_,u))}}function ms(x,w,N,F){let[Z,te,fe,ge]=N,we=w%2,Be=0;return we==0&&(ge||te)&&(Be=w==0&&!Z||w==2&&!fe?En(Zp.size/3):0),we==1&&(Z||fe)&&(Be=w==1&&!te||w==3&&!ge?En(jp.size/2):0),Be}let Vo=i.padding=(n.padding||[ms,ms,ms,ms]).map(x=>Tt(Dt(x,ms))),Di=i._padding=Vo.map((x,w)=>x(i,w,Zi,0)),on,dn=null,pn=null,Ji=s==1?v[0].idxs:null,ri=null,Fs=!1;function Ho(x,w){if(e=x??[],i.data=i._data=e,s==2){on=0;for(let N=1;N<v.length;N++)on+=e[N][0].length}else{e.length==0&&(i.data=i._data=e=[[]]),ri=e[0],on=ri.length;let N=e;if(G==2){N=e.slice();let F=N[0]=Array(on);for(let Z=0;Z<on;Z++)F[Z]=Z}i._data=e=N}if(gt(!0),Ln("setData"),G==2&&(be=!0),w!==!1){let N=L;N.auto(i,Fs)?Go():ks(T,N.min,N.max),ae=ae||oe.left>=0,xe=!0,zn()}}i.setData=Ho;function Go(){Fs=!0;let x,w;s==1&&(on>0?(dn=Ji[0]=0,pn=Ji[1]=on-1,x=e[0][dn],w=e[0][pn],G==2?(x=dn,w=pn):x==w&&(G==3?[x,w]=Cl(x,x,L.log,!1):G==4?[x,w]=Vu(x,x,L.log,!1):L.time?w=x+En(86400/m):[x,w]=Tl(x,w,Hu,!0))):(dn=Ji[0]=x=null,pn=Ji[1]=w=null)),ks(T,x,w)}let Ur,Os,Fr,E,Y,re,K,j,Ce,Ne;function Pe(x,w,N,F,Z,te){x??=wp,N??=Wu,F??="butt",Z??=wp,te??="round",x!=Ur&&(f.strokeStyle=Ur=x),Z!=Os&&(f.fillStyle=Os=Z),w!=Fr&&(f.lineWidth=Fr=w),te!=Y&&(f.lineJoin=Y=te),F!=re&&(f.lineCap=re=F),N!=E&&f.setLineDash(E=N)}function Fe(x,w,N,F){w!=Os&&(f.fillStyle=Os=w),x!=K&&(f.font=K=x),N!=j&&(f.textAlign=j=N),F!=Ce&&(f.textBaseline=Ce=F)}function qe(x,w,N,F,Z=0){if(F.length>0&&x.auto(i,Fs)&&(w==null||w.min==null)){let te=Dt(dn,0),fe=Dt(pn,F.length-1),ge=N.min==null?dx(F,te,fe,Z,x.distr==3):[N.min,N.max];x.min=ki(x.min,N.min=ge[0]),x.max=Kn(x.max,N.max=ge[1])}}let ot={min:null,max:null};function vt(){for(let F in S){let Z=S[F];U[F]==null&&(Z.min==null||U[T]!=null&&Z.auto(i,Fs))&&(U[F]=ot)}for(let F in S){let Z=S[F];U[F]==null&&Z.from!=null&&U[Z.from]!=null&&(U[F]=ot)}U[T]!=null&&gt(!0);let x={};for(let F in U){let Z=U[F];if(Z!=null){let te=x[F]=no(S[F],Mx);if(Z.min!=null)Sn(te,Z);else if(F!=T||s==2)if(on==0&&te.from==null){let fe=te.range(i,null,null,F);te.min=fe[0],te.max=fe[1]}else te.min=Yt,te.max=-Yt}}if(on>0){v.forEach((F,Z)=>{if(s==1){let te=F.scale,fe=U[te];if(fe==null)return;let ge=x[te];if(Z==0){let we=ge.range(i,ge.min,ge.max,te);ge.min=we[0],ge.max=we[1],dn=Bi(ge.min,e[0]),pn=Bi(ge.max,e[0]),pn-dn>1&&(e[0][dn]<ge.min&&dn++,e[0][pn]>ge.max&&pn--),F.min=ri[dn],F.max=ri[pn]}else F.show&&F.auto&&qe(ge,fe,F,e[Z],F.sorted);F.idxs[0]=dn,F.idxs[1]=pn}else if(Z>0&&F.show&&F.auto){let[te,fe]=F.facets,ge=te.scale,we=fe.scale,[Be,ke]=e[Z],Ge=x[ge],ht=x[we];Ge!=null&&qe(Ge,U[ge],te,Be,te.sorted),ht!=null&&qe(ht,U[we],fe,ke,fe.sorted),F.min=fe.min,F.max=fe.max}});for(let F in x){let Z=x[F],te=U[F];if(Z.from==null&&(te==null||te.min==null)){let fe=Z.range(i,Z.min==Yt?null:Z.min,Z.max==-Yt?null:Z.max,F);Z.min=fe[0],Z.max=fe[1]}}}for(let F in x){let Z=x[F];if(Z.from!=null){let te=x[Z.from];if(te.min==null)Z.min=Z.max=null;else{let fe=Z.range(i,te.min,te.max,F);Z.min=fe[0],Z.max=fe[1]}}}let w={},N=!1;for(let F in x){let Z=x[F],te=S[F];if(te.min!=Z.min||te.max!=Z.max){te.min=Z.min,te.max=Z.max;let fe=te.distr;te._min=fe==3?Ms(te.min):fe==4?wu(te.min,te.asinh):fe==100?te.fwd(te.min):te.min,te._max=fe==3?Ms(te.max):fe==4?wu(te.max,te.asinh):fe==100?te.fwd(te.max):te.max,w[F]=N=!0}}if(N){v.forEach((F,Z)=>{s==2?Z>0&&w.y&&(F._paths=null):w[F.scale]&&(F._paths=null)});for(let F in w)be=!0,Ln("setScale",F);_e&&oe.left>=0&&(ae=xe=!0)}for(let F in U)U[F]=null}function Xe(x){let w=Lu(dn-1,0,on-1),N=Lu(pn+1,0,on-1);for(;x[w]==null&&w>0;)w--;for(;x[N]==null&&N<on-1;)N++;return[w,N]}function St(){if(on>0){let x=v.some(w=>w._focus)&&Ne!=We.alpha;x&&(f.globalAlpha=Ne=We.alpha),v.forEach((w,N)=>{if(N>0&&w.show&&(sn(N,!1),sn(N,!0),w._paths==null)){let F=Ne;Ne!=w.alpha&&(f.globalAlpha=Ne=w.alpha);let Z=s==2?[0,e[N][0].length-1]:Xe(e[N]);w._paths=w.paths(i,N,Z[0],Z[1]),Ne!=F&&(f.globalAlpha=Ne=F)}}),v.forEach((w,N)=>{if(N>0&&w.show){let F=Ne;Ne!=w.alpha&&(f.globalAlpha=Ne=w.alpha),w._paths!=null&&Vt(N,!1);{let Z=w._paths!=null?w._paths.gaps:null,te=w.points.show(i,N,dn,pn,Z),fe=w.points.filter(i,N,te,Z);(te||fe)&&(w.points._paths=w.points.paths(i,N,dn,pn,fe),Vt(N,!0))}Ne!=F&&(f.globalAlpha=Ne=F),Ln("drawSeries",N)}}),x&&(f.globalAlpha=Ne=1)}}function sn(x,w){let N=w?v[x].points:v[x];N._stroke=N.stroke(i,x),N._fill=N.fill(i,x)}function Vt(x,w){let N=w?v[x].points:v[x],{stroke:F,fill:Z,clip:te,flags:fe,_stroke:ge=N._stroke,_fill:we=N._fill,_width:Be=N.width}=N._paths;Be=$t(Be*Ut,3);let ke=null,Ge=Be%2/2;w&&we==null&&(we=Be>0?"#fff":ge);let ht=N.pxAlign==1&&Ge>0;if(ht&&f.translate(Ge,Ge),!w){let Nt=I-Be/2,Lt=M-Be/2,wt=J+Be,nt=pe+Be;ke=new Path2D,ke.rect(Nt,Lt,wt,nt)}w?He(ge,Be,N.dash,N.cap,we,F,Z,fe,te):Ht(x,ge,Be,N.dash,N.cap,we,F,Z,fe,ke,te),ht&&f.translate(-Ge,-Ge)}function Ht(x,w,N,F,Z,te,fe,ge,we,Be,ke){let Ge=!1;we!=0&&P.forEach((ht,Nt)=>{if(ht.series[0]==x){let Lt=v[ht.series[1]],wt=e[ht.series[1]],nt=(Lt._paths||la).band;Ws(nt)&&(nt=ht.dir==1?nt[0]:nt[1]);let Ke,jt=null;Lt.show&&nt&&mx(wt,dn,pn)?(jt=ht.fill(i,Nt)||te,Ke=Lt._paths.clip):nt=null,He(w,N,F,Z,jt,fe,ge,we,Be,ke,Ke,nt),Ge=!0}}),Ge||He(w,N,F,Z,te,fe,ge,we,Be,ke)}let bn=io|Uu;function He(x,w,N,F,Z,te,fe,ge,we,Be,ke,Ge){Pe(x,w,N,F,Z),(we||Be||Ge)&&(f.save(),we&&f.clip(we),Be&&f.clip(Be)),Ge?(ge&bn)==bn?(f.clip(Ge),ke&&f.clip(ke),Et(Z,fe),gn(x,te,w)):ge&Uu?(Et(Z,fe),f.clip(Ge),gn(x,te,w)):ge&io&&(f.save(),f.clip(Ge),ke&&f.clip(ke),Et(Z,fe),f.restore(),gn(x,te,w)):(Et(Z,fe),gn(x,te,w)),(we||Be||Ge)&&f.restore()}function gn(x,w,N){N>0&&(w instanceof Map?w.forEach((F,Z)=>{f.strokeStyle=Ur=Z,f.stroke(F)}):w!=null&&x&&f.stroke(w))}function Et(x,w){w instanceof Map?w.forEach((N,F)=>{f.fillStyle=Os=F,f.fill(N)}):w!=null&&x&&f.fill(w)}function gs(x,w,N,F){let Z=C[x],te;if(F<=0)te=[0,0];else{let fe=Z._space=Z.space(i,x,w,N,F),ge=Z._incrs=Z.incrs(i,x,w,N,F,fe);te=Fy(w,N,ge,F,fe)}return Z._found=te}function _n(x,w,N,F,Z,te,fe,ge,we,Be){let ke=fe%2/2;b==1&&f.translate(ke,ke),Pe(ge,fe,we,Be,ge),f.beginPath();let Ge,ht,Nt,Lt,wt=Z+(F==0||F==3?-te:te);N==0?(ht=Z,Lt=wt):(Ge=Z,Nt=wt);for(let nt=0;nt<x.length;nt++)w[nt]!=null&&(N==0?Ge=Nt=x[nt]:ht=Lt=x[nt],f.moveTo(Ge,ht),f.lineTo(Nt,Lt));f.stroke(),b==1&&f.translate(-ke,-ke)}function Or(x){let w=!0;return C.forEach((N,F)=>{if(!N.show)return;let Z=S[N.scale];if(Z.min==null){N._show&&(w=!1,N._show=!1,gt(!1));return}else N._show||(w=!1,N._show=!0,gt(!1));let te=N.side,fe=te%2,{min:ge,max:we}=Z,[Be,ke]=gs(F,ge,we,fe==0?k:De);if(ke==0)return;let Ge=Z.distr==2,ht=N._splits=N.splits(i,F,ge,we,Be,ke,Ge),Nt=Z.distr==2?ht.map(Ke=>ri[Ke]):ht,Lt=Z.distr==2?ri[ht[1]]-ri[ht[0]]:Be,wt=N._values=N.values(i,N.filter(i,Nt,F,ke,Lt),F,ke,Lt);N._rotate=te==2?N.rotate(i,wt,F,ke):0;let nt=N._size;N._size=Pi(N.size(i,wt,F,x)),nt!=null&&N._size!=nt&&(w=!1)}),w}function Ki(x){let w=!0;return Vo.forEach((N,F)=>{let Z=N(i,F,Zi,x);Z!=Di[F]&&(w=!1),Di[F]=Z}),w}function _s(){for(let x=0;x<C.length;x++){let w=C[x];if(!w.show||!w._show)continue;let N=w.side,F=N%2,Z,te,fe=w.stroke(i,x),ge=N==0||N==3?-1:1,[we,Be]=w._found;if(w.label!=null){let $n=w.labelGap*ge,li=En((w._lpos+$n)*Ut);Fe(w.labelFont[0],fe,"center",N==2?"top":bp),f.save(),F==1?(Z=te=0,f.translate(li,En(M+pe/2)),f.rotate((N==3?-wl:wl)/2)):(Z=En(I+J/2),te=li);let dr=fm(w.label)?w.label(i,x,we,Be):w.label;f.fillText(dr,Z,te),f.restore()}if(Be==0)continue;let ke=S[w.scale],Ge=F==0?J:pe,ht=F==0?I:M,Nt=w._splits,Lt=ke.distr==2?Nt.map($n=>ri[$n]):Nt,wt=ke.distr==2?ri[Nt[1]]-ri[Nt[0]]:we,nt=w.ticks,Ke=w.border,jt=nt.show?nt.size:0,ln=En(jt*Ut),Dn=En((w.alignTo==2?w._size-jt-w.gap:w.gap)*Ut),Wt=w._rotate*-wl/180,cn=d(w._pos*Ut),oi=(ln+Dn)*ge,Yn=cn+oi;te=F==0?Yn:0,Z=F==1?Yn:0;let wi=w.font[0],Ni=w.align==1?Kr:w.align==2?Su:Wt>0?Kr:Wt<0?Su:F==0?"center":N==3?Su:Kr,es=Wt||F==1?"middle":N==2?"top":bp;Fe(wi,fe,Ni,es);let ai=w.font[1]*w.lineGap,Ei=Nt.map($n=>d(a($n,ke,Ge,ht))),Ui=w._values;for(let $n=0;$n<Ui.length;$n++){let li=Ui[$n];if(li!=null){F==0?Z=Ei[$n]:te=Ei[$n],li=""+li;let dr=li.indexOf(`
`)==-1?[li]:li.split(/\n/gm);for(let Zn=0;Zn<dr.length;Zn++){let Zd=dr[Zn];Wt?(f.save(),f.translate(Z,te+Zn*ai),f.rotate(Wt),f.fillText(Zd,0,0),f.restore()):f.fillText(Zd,Z,te+Zn*ai)}}}nt.show&&_n(Ei,nt.filter(i,Lt,x,Be,wt),F,N,cn,ln,$t(nt.width*Ut,3),nt.stroke(i,x),nt.dash,nt.cap);let ts=w.grid;ts.show&&_n(Ei,ts.filter(i,Lt,x,Be,wt),F,F==0?2:1,F==0?M:I,F==0?pe:J,$t(ts.width*Ut,3),ts.stroke(i,x),ts.dash,ts.cap),Ke.show&&_n([cn],[1],F==0?1:0,F==0?1:2,F==1?M:I,F==1?pe:J,$t(Ke.width*Ut,3),Ke.stroke(i,x),Ke.dash,Ke.cap)}Ln("drawAxes")}function gt(x){v.forEach((w,N)=>{N>0&&(w._paths=null,x&&(s==1?(w.min=null,w.max=null):w.facets.forEach(F=>{F.min=null,F.max=null})))})}let an=!1,qn=!1,Gt=[];function xn(){qn=!1;for(let x=0;x<Gt.length;x++)Ln(...Gt[x]);Gt.length=0}function zn(){an||(Cx(Id),an=!0)}function ja(x,w=!1){an=!0,qn=w,x(i),Id(),w&&Gt.length>0&&queueMicrotask(xn)}i.batch=ja;function Id(){if(ue&&(vt(),ue=!1),be&&(Re(),be=!1),Me){if(Qt(p,Kr,tt),Qt(p,"top",ut),Qt(p,sa,k),Qt(p,ra,De),Qt(g,Kr,tt),Qt(g,"top",ut),Qt(g,sa,k),Qt(g,ra,De),Qt(u,sa,mt),Qt(u,ra,bt),h.width=En(mt*Ut),h.height=En(bt*Ut),C.forEach(({_el:x,_show:w,_size:N,_pos:F,side:Z})=>{if(x!=null)if(w){let te=Z===3||Z===0?N:0,fe=Z%2==1;Qt(x,fe?"left":"top",F-te),Qt(x,fe?"width":"height",N),Qt(x,fe?"top":"left",fe?ut:tt),Qt(x,fe?"height":"width",fe?De:k),Pu(x,_r)}else fi(x,_r)}),Ur=Os=Fr=Y=re=K=j=Ce=E=null,Ne=1,qo(!0),tt!=Ae||ut!=Xt||k!=$e||De!=Qe){gt(!1);let x=k/$e,w=De/Qe;if(_e&&!ae&&oe.left>=0){oe.left*=x,oe.top*=w,Br&&rs(Br,En(oe.left),0,k,De),kr&&rs(kr,0,En(oe.top),k,De);for(let N=0;N<pt.length;N++){let F=pt[N];F!=null&&(Zt[N]*=x,Xn[N]*=w,rs(F,Pi(Zt[N]),Pi(Xn[N]),k,De))}}if(Kt.show&&!ce&&Kt.left>=0&&Kt.width>0){Kt.left*=x,Kt.width*=x,Kt.top*=w,Kt.height*=w;for(let N in $h)Qt(Hr,N,Kt[N])}Ae=tt,Xt=ut,$e=k,Qe=De}Ln("setSize"),Me=!1}mt>0&&bt>0&&(f.clearRect(0,0,h.width,h.height),Ln("drawClear"),R.forEach(x=>x()),Ln("draw")),Kt.show&&ce&&(Qa(Kt),ce=!1),_e&&ae&&(fr(null,!0,!1),ae=!1),ne.show&&ne.live&&xe&&(qh(),xe=!1),c||(c=!0,i.status=1,Ln("ready")),Fs=!1,an=!1}i.redraw=(x,w)=>{be=w||!1,x!==!1?ks(T,L.min,L.max):zn()};function Gh(x,w){let N=S[x];if(N.from==null){if(on==0){let F=N.range(i,w.min,w.max,x);w.min=F[0],w.max=F[1]}if(w.min>w.max){let F=w.min;w.min=w.max,w.max=F}if(on>1&&w.min!=null&&w.max!=null&&w.max-w.min<1e-16)return;x==T&&N.distr==2&&on>0&&(w.min=Bi(w.min,e[0]),w.max=Bi(w.max,e[0]),w.min==w.max&&w.max++),U[x]=w,ue=!0,zn()}}i.setScale=Gh;let Wh,Xh,Br,kr,Ld,Dd,zr,Vr,Nd,Ud,Jt,tn,Bs=!1,kn=oe.drag,Pn=kn.x,In=kn.y;_e&&(oe.x&&(Wh=Ci(Q_,g)),oe.y&&(Xh=Ci(ex,g)),L.ori==0?(Br=Wh,kr=Xh):(Br=Xh,kr=Wh),Jt=oe.left,tn=oe.top);let Kt=i.select=Sn({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),Hr=Kt.show?Ci(j_,Kt.over?g:p):null;function Qa(x,w){if(Kt.show){for(let N in x)Kt[N]=x[N],N in $h&&Qt(Hr,N,x[N]);w!==!1&&Ln("setSelect")}}i.setSelect=Qa;function Q0(x){if(v[x].show)se&&Pu(rt[x],_r);else if(se&&fi(rt[x],_r),_e){let N=Le?pt[0]:pt[x];N!=null&&rs(N,-10,-10,k,De)}}function ks(x,w,N){Gh(x,{min:w,max:N})}function ji(x,w,N,F){w.focus!=null&&s_(x),w.show!=null&&v.forEach((Z,te)=>{te>0&&(x==te||x==null)&&(Z.show=w.show,Q0(te),s==2?(ks(Z.facets[0].scale,null,null),ks(Z.facets[1].scale,null,null)):ks(Z.scale,null,null),zn())}),N!==!1&&Ln("setSeries",x,w),F&&Yo("setSeries",i,x,w)}i.setSeries=ji;function e_(x,w){Sn(P[x],w)}function t_(x,w){x.fill=Tt(x.fill||null),x.dir=Dt(x.dir,-1),w=w??P.length,P.splice(w,0,x)}function n_(x){x==null?P.length=0:P.splice(x,1)}i.addBand=t_,i.setBand=e_,i.delBand=n_;function i_(x,w){v[x].alpha=w,_e&&pt[x]!=null&&(pt[x].style.opacity=w),se&&rt[x]&&(rt[x].style.opacity=w)}let xs,zs,ur,Gr={focus:!0};function s_(x){if(x!=ur){let w=x==null,N=We.alpha!=1;v.forEach((F,Z)=>{if(s==1||Z>0){let te=w||Z==0||Z==x;F._focus=w?null:te,N&&i_(Z,te?1:We.alpha)}}),ur=x,N&&zn()}}se&&st&&je(Ap,Ee,x=>{oe._lock||(it(x),ur!=null&&ji(null,Gr,!0,yn.setSeries))});function Qi(x,w,N){let F=S[w];N&&(x=x/Ut-(F.ori==1?ut:tt));let Z=k;F.ori==1&&(Z=De,x=Z-x),F.dir==-1&&(x=Z-x);let te=F._min,fe=F._max,ge=x/Z,we=te+(fe-te)*ge,Be=F.distr;return Be==3?eo(10,we):Be==4?_x(we,F.asinh):Be==100?F.bwd(we):we}function r_(x,w){let N=Qi(x,T,w);return Bi(N,e[0],dn,pn)}i.valToIdx=x=>Bi(x,e[0]),i.posToIdx=r_,i.posToVal=Qi,i.valToPos=(x,w,N)=>S[w].ori==0?r(x,S[w],N?J:k,N?I:0):o(x,S[w],N?pe:De,N?M:0),i.setCursor=(x,w,N)=>{Jt=x.left,tn=x.top,fr(null,w,N)};function Fd(x,w){Qt(Hr,Kr,Kt.left=x),Qt(Hr,sa,Kt.width=w)}function Od(x,w){Qt(Hr,"top",Kt.top=x),Qt(Hr,ra,Kt.height=w)}let Wo=L.ori==0?Fd:Od,Xo=L.ori==1?Fd:Od;function o_(){if(se&&ne.live)for(let x=s==2?1:0;x<v.length;x++){if(x==0&&Ue)continue;let w=ne.values[x],N=0;for(let F in w)Ye[x][N++].firstChild.nodeValue=w[F]}}function qh(x,w){if(x!=null&&(x.idxs?x.idxs.forEach((N,F)=>{$[F]=N}):Sx(x.idx)||$.fill(x.idx),ne.idx=$[0]),se&&ne.live){for(let N=0;N<v.length;N++)(N>0||s==1&&!Ue)&&a_(N,$[N]);o_()}xe=!1,w!==!1&&Ln("setLegend")}i.setLegend=qh;function a_(x,w){let N=v[x],F=x==0&&G==2?ri:e[x],Z;Ue?Z=N.values(i,x,w)??Ve:(Z=N.value(i,w==null?null:F[w],x,w),Z=Z==null?Ve:{_:Z}),ne.values[x]=Z}function fr(x,w,N){Nd=Jt,Ud=tn,[Jt,tn]=oe.move(i,Jt,tn),oe.left=Jt,oe.top=tn,_e&&(Br&&rs(Br,En(Jt),0,k,De),kr&&rs(kr,0,En(tn),k,De));let F,Z=dn>pn;xs=Yt,zs=null;let te=L.ori==0?k:De,fe=L.ori==1?k:De;if(Jt<0||on==0||Z){F=oe.idx=null;for(let ge=0;ge<v.length;ge++){let we=pt[ge];we!=null&&rs(we,-10,-10,k,De)}st&&ji(null,Gr,!0,x==null&&yn.setSeries),ne.live&&($.fill(F),xe=!0)}else{let ge,we,Be;s==1&&(ge=L.ori==0?Jt:tn,we=Qi(ge,T),F=oe.idx=Bi(we,e[0],dn,pn),Be=X(e[0][F],L,te,0));let ke=-10,Ge=-10,ht=0,Nt=0,Lt=!0,wt="",nt="";for(let Ke=s==2?1:0;Ke<v.length;Ke++){let jt=v[Ke],ln=$[Ke],Dn=ln==null?null:s==1?e[Ke][ln]:e[Ke][1][ln],Wt=oe.dataIdx(i,Ke,F,we),cn=Wt==null?null:s==1?e[Ke][Wt]:e[Ke][1][Wt];if(xe=xe||cn!=Dn||Wt!=ln,$[Ke]=Wt,Ke>0&&jt.show){let oi=Wt==null?-10:Wt==F?Be:X(s==1?e[0][Wt]:e[Ke][0][Wt],L,te,0),Yn=cn==null?-10:y(cn,s==1?S[jt.scale]:S[jt.facets[1].scale],fe,0);if(st&&cn!=null){let wi=L.ori==1?Jt:tn,Ni=Tn(We.dist(i,Ke,Wt,Yn,wi));if(Ni<xs){let es=We.bias;if(es!=0){let ai=Qi(wi,jt.scale),Ei=cn>=0?1:-1,Ui=ai>=0?1:-1;Ui==Ei&&(Ui==1?es==1?cn>=ai:cn<=ai:es==1?cn<=ai:cn>=ai)&&(xs=Ni,zs=Ke)}else xs=Ni,zs=Ke}}if(xe||Le){let wi,Ni;L.ori==0?(wi=oi,Ni=Yn):(wi=Yn,Ni=oi);let es,ai,Ei,Ui,ts,$n,li=!0,dr=de.bbox;if(dr!=null){li=!1;let Zn=dr(i,Ke);Ei=Zn.left,Ui=Zn.top,es=Zn.width,ai=Zn.height}else Ei=wi,Ui=Ni,es=ai=de.size(i,Ke);if($n=de.fill(i,Ke),ts=de.stroke(i,Ke),Le)Ke==zs&&xs<=We.prox&&(ke=Ei,Ge=Ui,ht=es,Nt=ai,Lt=li,wt=$n,nt=ts);else{let Zn=pt[Ke];Zn!=null&&(Zt[Ke]=Ei,Xn[Ke]=Ui,Np(Zn,es,ai,li),Lp(Zn,$n,ts),rs(Zn,Pi(Ei),Pi(Ui),k,De))}}}}if(Le){let Ke=We.prox,jt=ur==null?xs<=Ke:xs>Ke||zs!=ur;if(xe||jt){let ln=pt[0];ln!=null&&(Zt[0]=ke,Xn[0]=Ge,Np(ln,ht,Nt,Lt),Lp(ln,wt,nt),rs(ln,Pi(ke),Pi(Ge),k,De))}}}if(Kt.show&&Bs)if(x!=null){let[ge,we]=yn.scales,[Be,ke]=yn.match,[Ge,ht]=x.cursor.sync.scales,Nt=x.cursor.drag;if(Pn=Nt._x,In=Nt._y,Pn||In){let{left:Lt,top:wt,width:nt,height:Ke}=x.select,jt=x.scales[Ge].ori,ln=x.posToVal,Dn,Wt,cn,oi,Yn,wi=ge!=null&&Be(ge,Ge),Ni=we!=null&&ke(we,ht);wi&&Pn?(jt==0?(Dn=Lt,Wt=nt):(Dn=wt,Wt=Ke),cn=S[ge],oi=X(ln(Dn,Ge),cn,te,0),Yn=X(ln(Dn+Wt,Ge),cn,te,0),Wo(ki(oi,Yn),Tn(Yn-oi))):Wo(0,te),Ni&&In?(jt==1?(Dn=Lt,Wt=nt):(Dn=wt,Wt=Ke),cn=S[we],oi=y(ln(Dn,ht),cn,fe,0),Yn=y(ln(Dn+Wt,ht),cn,fe,0),Xo(ki(oi,Yn),Tn(Yn-oi))):Xo(0,fe)}else Zh()}else{let ge=Tn(Nd-Ld),we=Tn(Ud-Dd);if(L.ori==1){let ht=ge;ge=we,we=ht}Pn=kn.x&&ge>=kn.dist,In=kn.y&&we>=kn.dist;let Be=kn.uni;Be!=null?Pn&&In&&(Pn=ge>=Be,In=we>=Be,!Pn&&!In&&(we>ge?In=!0:Pn=!0)):kn.x&&kn.y&&(Pn||In)&&(Pn=In=!0);let ke,Ge;Pn&&(L.ori==0?(ke=zr,Ge=Jt):(ke=Vr,Ge=tn),Wo(ki(ke,Ge),Tn(Ge-ke)),In||Xo(0,fe)),In&&(L.ori==1?(ke=zr,Ge=Jt):(ke=Vr,Ge=tn),Xo(ki(ke,Ge),Tn(Ge-ke)),Pn||Wo(0,te)),!Pn&&!In&&(Wo(0,0),Xo(0,0))}if(kn._x=Pn,kn._y=In,x==null){if(N){if($d!=null){let[ge,we]=yn.scales;yn.values[0]=ge!=null?Qi(L.ori==0?Jt:tn,ge):null,yn.values[1]=we!=null?Qi(L.ori==1?Jt:tn,we):null}Yo(Mu,i,Jt,tn,k,De,F)}if(st){let ge=N&&yn.setSeries,we=We.prox;ur==null?xs<=we&&ji(zs,Gr,!0,ge):xs>we?ji(null,Gr,!0,ge):zs!=ur&&ji(zs,Gr,!0,ge)}}xe&&(ne.idx=F,qh()),w!==!1&&Ln("setCursor")}let Vs=null;Object.defineProperty(i,"rect",{get(){return Vs==null&&qo(!1),Vs}});function qo(x=!1){x?Vs=null:(Vs=g.getBoundingClientRect(),Ln("syncRect",Vs))}function Bd(x,w,N,F,Z,te,fe){oe._lock||Bs&&x!=null&&x.movementX==0&&x.movementY==0||(Yh(x,w,N,F,Z,te,fe,!1,x!=null),x!=null?fr(null,!0,!0):fr(w,!0,!1))}function Yh(x,w,N,F,Z,te,fe,ge,we){if(Vs==null&&qo(!1),it(x),x!=null)N=x.clientX-Vs.left,F=x.clientY-Vs.top;else{if(N<0||F<0){Jt=-10,tn=-10;return}let[Be,ke]=yn.scales,Ge=w.cursor.sync,[ht,Nt]=Ge.values,[Lt,wt]=Ge.scales,[nt,Ke]=yn.match,jt=w.axes[0].side%2==1,ln=L.ori==0?k:De,Dn=L.ori==1?k:De,Wt=jt?te:Z,cn=jt?Z:te,oi=jt?F:N,Yn=jt?N:F;if(Lt!=null?N=nt(Be,Lt)?a(ht,S[Be],ln,0):-10:N=ln*(oi/Wt),wt!=null?F=Ke(ke,wt)?a(Nt,S[ke],Dn,0):-10:F=Dn*(Yn/cn),L.ori==1){let wi=N;N=F,F=wi}}we&&(w==null||w.cursor.event.type==Mu)&&((N<=1||N>=k-1)&&(N=mr(N,k)),(F<=1||F>=De-1)&&(F=mr(F,De))),ge?(Ld=N,Dd=F,[zr,Vr]=oe.move(i,N,F)):(Jt=N,tn=F)}let $h={width:0,height:0,left:0,top:0};function Zh(){Qa($h,!1)}let kd,zd,Vd,Hd;function Gd(x,w,N,F,Z,te,fe){Bs=!0,Pn=In=kn._x=kn._y=!1,Yh(x,w,N,F,Z,te,fe,!0,!1),x!=null&&(je(bu,Ru,Wd,!1),Yo(Ep,i,zr,Vr,k,De,null));let{left:ge,top:we,width:Be,height:ke}=Kt;kd=ge,zd=we,Vd=Be,Hd=ke}function Wd(x,w,N,F,Z,te,fe){Bs=kn._x=kn._y=!1,Yh(x,w,N,F,Z,te,fe,!1,!0);let{left:ge,top:we,width:Be,height:ke}=Kt,Ge=Be>0||ke>0,ht=kd!=ge||zd!=we||Vd!=Be||Hd!=ke;if(Ge&&ht&&Qa(Kt),kn.setScale&&Ge&&ht){let Nt=ge,Lt=Be,wt=we,nt=ke;if(L.ori==1&&(Nt=we,Lt=ke,wt=ge,nt=Be),Pn&&ks(T,Qi(Nt,T),Qi(Nt+Lt,T)),In)for(let Ke in S){let jt=S[Ke];Ke!=T&&jt.from==null&&jt.min!=Yt&&ks(Ke,Qi(wt+nt,Ke),Qi(wt,Ke))}Zh()}else oe.lock&&(oe._lock=!oe._lock,fr(w,!0,x!=null));x!=null&&(dt(bu,Ru),Yo(bu,i,Jt,tn,k,De,null))}function l_(x,w,N,F,Z,te,fe){if(oe._lock)return;it(x);let ge=Bs;if(Bs){let we=!0,Be=!0,ke=10,Ge,ht;L.ori==0?(Ge=Pn,ht=In):(Ge=In,ht=Pn),Ge&&ht&&(we=Jt<=ke||Jt>=k-ke,Be=tn<=ke||tn>=De-ke),Ge&&we&&(Jt=Jt<zr?0:k),ht&&Be&&(tn=tn<Vr?0:De),fr(null,!0,!0),Bs=!1}Jt=-10,tn=-10,$.fill(null),fr(null,!0,!0),ge&&(Bs=ge)}function Xd(x,w,N,F,Z,te,fe){oe._lock||(it(x),Go(),Zh(),x!=null&&Yo(Rp,i,Jt,tn,k,De,null))}function qd(){C.forEach(Oy),V(i.width,i.height,!0)}xr(El,Qr,qd);let Wr={};Wr.mousedown=Gd,Wr.mousemove=Bd,Wr.mouseup=Wd,Wr.dblclick=Xd,Wr.setSeries=(x,w,N,F)=>{let Z=yn.match[2];N=Z(i,w,N),N!=-1&&ji(N,F,!0,!1)},_e&&(je(Ep,g,Gd),je(Mu,g,Bd),je(Tp,g,x=>{it(x),qo(!1)}),je(Ap,g,l_),je(Rp,g,Xd),Fu.add(i),i.syncRect=qo);let el=i.hooks=n.hooks||{};function Ln(x,w,N){qn?Gt.push([x,w,N]):x in el&&el[x].forEach(F=>{F.call(null,i,w,N)})}(n.plugins||[]).forEach(x=>{for(let w in x.hooks)el[w]=(el[w]||[]).concat(x.hooks[w])});let Yd=(x,w,N)=>N,yn=Sn({key:null,setSeries:!1,filters:{pub:kp,sub:kp},scales:[T,v[1]?v[1].scale:null],match:[zp,zp,Yd],values:[null,null]},oe.sync);yn.match.length==2&&yn.match.push(Yd),oe.sync=yn;let $d=yn.key,Jh=Fm($d);function Yo(x,w,N,F,Z,te,fe){yn.filters.pub(x,w,N,F,Z,te,fe)&&Jh.pub(x,w,N,F,Z,te,fe)}Jh.sub(i);function c_(x,w,N,F,Z,te,fe){yn.filters.sub(x,w,N,F,Z,te,fe)&&Wr[x](null,w,N,F,Z,te,fe)}i.pub=c_;function h_(){Jh.unsub(i),Fu.delete(i),It.clear(),Iu(El,Qr,qd),l.remove(),Ee?.remove(),Ln("destroy")}i.destroy=h_;function Kh(){Ln("init",n,e),Ho(e||n.data,!1),U[T]?Gh(T,U[T]):Go(),ce=Kt.show&&(Kt.width>0||Kt.height>0),ae=xe=!0,V(n.width,n.height)}return v.forEach(Nr),C.forEach(ps),t?t instanceof HTMLElement?(t.appendChild(l),Kh()):t(i,Kh):Kh(),i}Un.assign=Sn;Un.fmtNum=Gu;Un.rangeNum=Tl;Un.rangeLog=Cl;Un.rangeAsinh=Vu;Un.orient=vr;Un.pxRatio=Ut;Un.join=Rx;Un.fmtDate=Xu,Un.tzDate=kx;Un.sync=Fm;{Un.addGap=Sy,Un.clipGaps=Ll;let n=Un.paths={points:Hm};n.linear=Wm,n.stepped=wy,n.bars=Ey,n.spline=Ay}var Sr=class{constructor(e,t){this.keep=t;this.ys=Array.from({length:e},()=>[])}keep;t=[];ys;push(e,...t){if(this.t.push(e),t.forEach((i,s)=>this.ys[s].push(i!=null&&Number.isFinite(i)?i:null)),this.t.length>this.keep){this.t.shift();for(let i of this.ys)i.shift()}}},ao=class{constructor(e,t,i,s=120,r=28){this.s=t;let o=document.createElement("span");o.className="spark",e.appendChild(o),this.plot=new Un({width:s,height:r,cursor:{show:!1},legend:{show:!1},select:{show:!1},axes:[{show:!1},{show:!1}],scales:{x:{time:!1},y:{range:(a,c,l)=>[Math.min(0,c),l>0?l*1.1:1]}},series:[{},{stroke:i,width:1.5,fill:i+"33",points:{show:!1}}]},[[],[]],o),o.appendChild(this.label)}s;plot;label=document.createElement("span");update(e){this.plot.setData([this.s.t,this.s.ys[0]]),this.label.textContent=e}destroy(){this.plot.destroy()}},Fl=class{constructor(e,t,i,s,r){this.s=t;this.plot=new Un({width:s,height:r,scales:{x:{time:!0}},axes:[{stroke:"#8a96a3",grid:{stroke:"#1f2a35"}},{stroke:"#8a96a3",grid:{stroke:"#1f2a35"},scale:i[0].scale},...i.some(o=>o.scale==="r")?[{side:1,scale:"r",stroke:"#8a96a3",grid:{show:!1}}]:[]],series:[{},...i.map(o=>({label:o.label,stroke:o.colour,width:1.5,scale:o.scale,points:{show:!1}}))]},[[],...i.map(()=>[])],e)}s;plot;update(){this.plot.setData([this.s.t,...this.s.ys])}destroy(){this.plot.destroy()}};var rr={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},or={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},Mg=0,Tf=1,bg=2;var ka=1,wg=2,Do=3,ar=0,ei=1,hs=2,Rr=0,No=1,Af=2,Rf=3,Cf=4,Eg=5;var Cr=100,Tg=101,Ag=102,Rg=103,Cg=104,Pg=200,Ig=201,Lg=202,Dg=203,Pf=204,If=205,Ng=206,Ug=207,Fg=208,Og=209,Bg=210,kg=211,zg=212,Vg=213,Hg=214,cc=0,hc=1,uc=2,bo=3,fc=4,dc=5,pc=6,mc=7,Lf=0,Gg=1,Wg=2,us=0,Df=1,Nf=2,Uf=3,Ff=4,Of=5,Bf=6,kf=7;var zf=300,Pr=301,Uo=302,Wc=303,Xc=304,gc=1e3,as=1001,_c=1002,Bn=1003,Xg=1004;var za=1005;var Qn=1006,qc=1007;var Ds=1008;var bi=1009,Vf=1010,Hf=1011,Fo=1012,Yc=1013,Wi=1014,Xi=1015,qi=1016,$c=1017,Zc=1018,Ir=1020,Gf=35902,Wf=35899,Xf=1021,qf=1022,Yi=1023,Ps=1026,Ns=1027,Yf=1028,Jc=1029,lr=1030,Kc=1031;var jc=1033,Va=33776,Ha=33777,Ga=33778,Wa=33779,Qc=35840,eh=35841,th=35842,nh=35843,ih=36196,sh=37492,rh=37496,oh=37488,ah=37489,Xa=37490,lh=37491,ch=37808,hh=37809,uh=37810,fh=37811,dh=37812,ph=37813,mh=37814,gh=37815,_h=37816,xh=37817,yh=37818,vh=37819,Sh=37820,Mh=37821,bh=36492,wh=36494,Eh=36495,Th=36283,Ah=36284,qa=36285,Rh=36286;var xa=2300,xc=2301,ac=2302,yf=2303,vf=2400,Sf=2401,Mf=2402;var qg=3200;var $f=0,Yg=1,Us="",_i="srgb",ya="srgb-linear",va="linear",kt="srgb";var lc=7680;var $g=519,Zg=512,Jg=513,Kg=514,Zf=515,jg=516,Qg=517,Jf=518,Kf=519,e0=35044;var jf="300 es",Li=2e3,Sa=2001;function By(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function ky(n){return ArrayBuffer.isView(n)&&!(n instanceof DataView)}function Ma(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function t0(){let n=Ma("canvas");return n.style.display="block",n}var $m={},wo=null;function Qf(...n){let e="THREE."+n.shift();wo?wo("log",e,...n):console.log(e,...n)}function n0(n){let e=n[0];if(typeof e=="string"&&e.startsWith("TSL:")){let t=n[1];t&&t.isStackTrace?n[0]+=" "+t.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function et(...n){n=n0(n);let e="THREE."+n.shift();if(wo)wo("warn",e,...n);else{let t=n[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...n)}}function at(...n){n=n0(n);let e="THREE."+n.shift();if(wo)wo("error",e,...n);else{let t=n[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...n)}}function ma(...n){let e=n.join(" ");e in $m||($m[e]=!0,et(...n))}function i0(n,e,t){return new Promise(function(i,s){function r(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:s();break;case n.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:i()}}setTimeout(r,t)})}var s0={[cc]:cc,[uc]:pc,[fc]:fc,[bo]:dc,[hc]:hc,[pc]:uc,[mc]:mc,[dc]:bo},Gi=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let i=this._listeners;i[e]===void 0&&(i[e]=[]),i[e].indexOf(t)===-1&&i[e].push(t)}hasEventListener(e,t){let i=this._listeners;return i===void 0?!1:i[e]!==void 0&&i[e].indexOf(t)!==-1}removeEventListener(e,t){let i=this._listeners;if(i===void 0)return;let s=i[e];if(s!==void 0){let r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){let t=this._listeners;if(t===void 0)return;let i=t[e.type];if(i!==void 0){e.target=this;let s=i.slice(0);for(let r=0,o=s.length;r<o;r++)s[r].call(this,e);e.target=null}}},Hn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],Zm=1234567,ga=Math.PI/180,Eo=180/Math.PI;function Oo(){let n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(Hn[n&255]+Hn[n>>8&255]+Hn[n>>16&255]+Hn[n>>24&255]+"-"+Hn[e&255]+Hn[e>>8&255]+"-"+Hn[e>>16&15|64]+Hn[e>>24&255]+"-"+Hn[t&63|128]+Hn[t>>8&255]+"-"+Hn[t>>16&255]+Hn[t>>24&255]+Hn[i&255]+Hn[i>>8&255]+Hn[i>>16&255]+Hn[i>>24&255]).toLowerCase()}function Mt(n,e,t){return Math.max(e,Math.min(t,n))}function ed(n,e){return(n%e+e)%e}function zy(n,e,t,i,s){return i+(n-e)*(s-i)/(t-e)}function Vy(n,e,t){return n!==e?(t-n)/(e-n):0}function _a(n,e,t){return(1-t)*n+t*e}function Hy(n,e,t,i){return _a(n,e,1-Math.exp(-t*i))}function Gy(n,e=1){return e-Math.abs(ed(n,e*2)-e)}function Wy(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*(3-2*n))}function Xy(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*n*(n*(n*6-15)+10))}function qy(n,e){return n+Math.floor(Math.random()*(e-n+1))}function Yy(n,e){return n+Math.random()*(e-n)}function $y(n){return n*(.5-Math.random())}function Zy(n){n!==void 0&&(Zm=n);let e=Zm+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function Jy(n){return n*ga}function Ky(n){return n*Eo}function jy(n){return n>0&&Number.isInteger(n)&&2**Math.round(Math.log2(n))===n}function Qy(n){return Math.pow(2,Math.ceil(Math.log(n)/Math.LN2))}function td(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function ev(n,e,t,i,s){let r=Math.cos,o=Math.sin,a=r(t/2),c=o(t/2),l=r((e+i)/2),h=o((e+i)/2),f=r((e-i)/2),u=o((e-i)/2),p=r((i-e)/2),g=o((i-e)/2);switch(s){case"XYX":n.set(a*h,c*f,c*u,a*l);break;case"YZY":n.set(c*u,a*h,c*f,a*l);break;case"ZXZ":n.set(c*f,c*u,a*h,a*l);break;case"XZX":n.set(a*h,c*g,c*p,a*l);break;case"YXY":n.set(c*p,a*h,c*g,a*l);break;case"ZYZ":n.set(c*g,c*p,a*h,a*l);break;default:et("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+s)}}function nd(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function r0(n,e){if(e.constructor===Float32Array)return n;let t=nd(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/t,-1)}function o0(n,e){if(e.constructor===Float32Array)return n;let t=nd(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*t)}var id={DEG2RAD:ga,RAD2DEG:Eo,generateUUID:Oo,clamp:Mt,euclideanModulo:ed,mapLinear:zy,inverseLerp:Vy,lerp:_a,damp:Hy,pingpong:Gy,smoothstep:Wy,smootherstep:Xy,randInt:qy,randFloat:Yy,randFloatSpread:$y,seededRandom:Zy,degToRad:Jy,radToDeg:Ky,isPowerOfTwo:jy,ceilPowerOfTwo:Qy,floorPowerOfTwo:td,setQuaternionFromProperEuler:ev,normalize:o0,denormalize:r0},ld=class ld{constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,i=this.y,s=e.elements;return this.x=s[0]*t+s[3]*i+s[6],this.y=s[1]*t+s[4]*i+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=Mt(this.x,e.x,t.x),this.y=Mt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=Mt(this.x,e,t),this.y=Mt(this.y,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(Mt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(Mt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y;return t*t+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let i=Math.cos(t),s=Math.sin(t),r=this.x-e.x,o=this.y-e.y;return this.x=r*i-o*s+e.x,this.y=r*s+o*i+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};ld.prototype.isVector2=!0;var ft=ld,vi=class{constructor(e=0,t=0,i=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=i,this._w=s}static slerpFlat(e,t,i,s,r,o,a){let c=i[s+0],l=i[s+1],h=i[s+2],f=i[s+3],u=r[o+0],p=r[o+1],g=r[o+2],b=r[o+3];if(f!==b||c!==u||l!==p||h!==g){let d=c*u+l*p+h*g+f*b;d<0&&(u=-u,p=-p,g=-g,b=-b,d=-d);let m=1-a;if(d<.9995){let v=Math.acos(d),C=Math.sin(v);m=Math.sin(m*v)/C,a=Math.sin(a*v)/C,c=c*m+u*a,l=l*m+p*a,h=h*m+g*a,f=f*m+b*a}else{c=c*m+u*a,l=l*m+p*a,h=h*m+g*a,f=f*m+b*a;let v=1/Math.sqrt(c*c+l*l+h*h+f*f);c*=v,l*=v,h*=v,f*=v}}e[t]=c,e[t+1]=l,e[t+2]=h,e[t+3]=f}static multiplyQuaternionsFlat(e,t,i,s,r,o){let a=i[s],c=i[s+1],l=i[s+2],h=i[s+3],f=r[o],u=r[o+1],p=r[o+2],g=r[o+3];return e[t]=a*g+h*f+c*p-l*u,e[t+1]=c*g+h*u+l*f-a*p,e[t+2]=l*g+h*p+a*u-c*f,e[t+3]=h*g-a*f-c*u-l*p,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,i,s){return this._x=e,this._y=t,this._z=i,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let i=e._x,s=e._y,r=e._z,o=e._order,a=Math.cos,c=Math.sin,l=a(i/2),h=a(s/2),f=a(r/2),u=c(i/2),p=c(s/2),g=c(r/2);switch(o){case"XYZ":this._x=u*h*f+l*p*g,this._y=l*p*f-u*h*g,this._z=l*h*g+u*p*f,this._w=l*h*f-u*p*g;break;case"YXZ":this._x=u*h*f+l*p*g,this._y=l*p*f-u*h*g,this._z=l*h*g-u*p*f,this._w=l*h*f+u*p*g;break;case"ZXY":this._x=u*h*f-l*p*g,this._y=l*p*f+u*h*g,this._z=l*h*g+u*p*f,this._w=l*h*f-u*p*g;break;case"ZYX":this._x=u*h*f-l*p*g,this._y=l*p*f+u*h*g,this._z=l*h*g-u*p*f,this._w=l*h*f+u*p*g;break;case"YZX":this._x=u*h*f+l*p*g,this._y=l*p*f+u*h*g,this._z=l*h*g-u*p*f,this._w=l*h*f-u*p*g;break;case"XZY":this._x=u*h*f-l*p*g,this._y=l*p*f-u*h*g,this._z=l*h*g+u*p*f,this._w=l*h*f+u*p*g;break;default:et("Quaternion: .setFromEuler() encountered an unknown order: "+o)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let i=t/2,s=Math.sin(i);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,i=t[0],s=t[4],r=t[8],o=t[1],a=t[5],c=t[9],l=t[2],h=t[6],f=t[10],u=i+a+f;if(u>0){let p=.5/Math.sqrt(u+1);this._w=.25/p,this._x=(h-c)*p,this._y=(r-l)*p,this._z=(o-s)*p}else if(i>a&&i>f){let p=2*Math.sqrt(1+i-a-f);this._w=(h-c)/p,this._x=.25*p,this._y=(s+o)/p,this._z=(r+l)/p}else if(a>f){let p=2*Math.sqrt(1+a-i-f);this._w=(r-l)/p,this._x=(s+o)/p,this._y=.25*p,this._z=(c+h)/p}else{let p=2*Math.sqrt(1+f-i-a);this._w=(o-s)/p,this._x=(r+l)/p,this._y=(c+h)/p,this._z=.25*p}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let i=e.dot(t)+1;return i<1e-8?(i=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=i):(this._x=0,this._y=-e.z,this._z=e.y,this._w=i)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=i),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(Mt(this.dot(e),-1,1)))}rotateTowards(e,t){let i=this.angleTo(e);if(i===0)return this;let s=Math.min(1,t/i);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=t._x,c=t._y,l=t._z,h=t._w;return this._x=i*h+o*a+s*l-r*c,this._y=s*h+o*c+r*a-i*l,this._z=r*h+o*l+i*c-s*a,this._w=o*h-i*a-s*c-r*l,this._onChangeCallback(),this}slerp(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=this.dot(e);a<0&&(i=-i,s=-s,r=-r,o=-o,a=-a);let c=1-t;if(a<.9995){let l=Math.acos(a),h=Math.sin(l);c=Math.sin(c*l)/h,t=Math.sin(t*l)/h,this._x=this._x*c+i*t,this._y=this._y*c+s*t,this._z=this._z*c+r*t,this._w=this._w*c+o*t,this._onChangeCallback()}else this._x=this._x*c+i*t,this._y=this._y*c+s*t,this._z=this._z*c+r*t,this._w=this._w*c+o*t,this.normalize();return this}slerpQuaternions(e,t,i){return this.copy(e).slerp(t,i)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),i=Math.random(),s=Math.sqrt(1-i),r=Math.sqrt(i);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},cd=class cd{constructor(e=0,t=0,i=0){this.x=e,this.y=t,this.z=i}set(e,t,i){return i===void 0&&(i=this.z),this.x=e,this.y=t,this.z=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(Jm.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(Jm.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*i+r[6]*s,this.y=r[1]*t+r[4]*i+r[7]*s,this.z=r[2]*t+r[5]*i+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=e.elements,o=1/(r[3]*t+r[7]*i+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*i+r[8]*s+r[12])*o,this.y=(r[1]*t+r[5]*i+r[9]*s+r[13])*o,this.z=(r[2]*t+r[6]*i+r[10]*s+r[14])*o,this}applyQuaternion(e){let t=this.x,i=this.y,s=this.z,r=e.x,o=e.y,a=e.z,c=e.w,l=2*(o*s-a*i),h=2*(a*t-r*s),f=2*(r*i-o*t);return this.x=t+c*l+o*f-a*h,this.y=i+c*h+a*l-r*f,this.z=s+c*f+r*h-o*l,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*i+r[8]*s,this.y=r[1]*t+r[5]*i+r[9]*s,this.z=r[2]*t+r[6]*i+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=Mt(this.x,e.x,t.x),this.y=Mt(this.y,e.y,t.y),this.z=Mt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=Mt(this.x,e,t),this.y=Mt(this.y,e,t),this.z=Mt(this.z,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(Mt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let i=e.x,s=e.y,r=e.z,o=t.x,a=t.y,c=t.z;return this.x=s*c-r*a,this.y=r*o-i*c,this.z=i*a-s*o,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let i=e.dot(this)/t;return this.copy(e).multiplyScalar(i)}projectOnPlane(e){return ju.copy(this).projectOnVector(e),this.sub(ju)}reflect(e){return this.sub(ju.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(Mt(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y,s=this.z-e.z;return t*t+i*i+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,i){let s=Math.sin(t)*e;return this.x=s*Math.sin(i),this.y=Math.cos(t)*e,this.z=s*Math.cos(i),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,i){return this.x=e*Math.sin(t),this.y=i,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),i=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=i,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,i=Math.sqrt(1-t*t);return this.x=i*Math.cos(e),this.y=t,this.z=i*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};cd.prototype.isVector3=!0;var ee=cd,ju=new ee,Jm=new vi,hd=class hd{constructor(e,t,i,s,r,o,a,c,l){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,c,l)}set(e,t,i,s,r,o,a,c,l){let h=this.elements;return h[0]=e,h[1]=s,h[2]=a,h[3]=t,h[4]=r,h[5]=c,h[6]=i,h[7]=o,h[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],this}extractBasis(e,t,i){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[3],c=i[6],l=i[1],h=i[4],f=i[7],u=i[2],p=i[5],g=i[8],b=s[0],d=s[3],m=s[6],v=s[1],C=s[4],S=s[7],P=s[2],T=s[5],_=s[8];return r[0]=o*b+a*v+c*P,r[3]=o*d+a*C+c*T,r[6]=o*m+a*S+c*_,r[1]=l*b+h*v+f*P,r[4]=l*d+h*C+f*T,r[7]=l*m+h*S+f*_,r[2]=u*b+p*v+g*P,r[5]=u*d+p*C+g*T,r[8]=u*m+p*S+g*_,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],c=e[6],l=e[7],h=e[8];return t*o*h-t*a*l-i*r*h+i*a*c+s*r*l-s*o*c}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],c=e[6],l=e[7],h=e[8],f=h*o-a*l,u=a*c-h*r,p=l*r-o*c,g=t*f+i*u+s*p;if(g===0)return this.set(0,0,0,0,0,0,0,0,0);let b=1/g;return e[0]=f*b,e[1]=(s*l-h*i)*b,e[2]=(a*i-s*o)*b,e[3]=u*b,e[4]=(h*t-s*c)*b,e[5]=(s*r-a*t)*b,e[6]=p*b,e[7]=(i*c-l*t)*b,e[8]=(o*t-i*r)*b,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,i,s,r,o,a){let c=Math.cos(r),l=Math.sin(r);return this.set(i*c,i*l,-i*(c*o+l*a)+o+e,-s*l,s*c,-s*(-l*o+c*a)+a+t,0,0,1),this}scale(e,t){return ma("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(Qu.makeScale(e,t)),this}rotate(e){return ma("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(Qu.makeRotation(-e)),this}translate(e,t){return ma("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(Qu.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,i,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<9;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<9;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e}clone(){return new this.constructor().fromArray(this.elements)}};hd.prototype.isMatrix3=!0;var lt=hd,Qu=new lt,Km=new lt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),jm=new lt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function tv(){let n={enabled:!0,workingColorSpace:ya,spaces:{},convert:function(s,r,o){return this.enabled===!1||r===o||!r||!o||(this.spaces[r].transfer===kt&&(s.r=Cs(s.r),s.g=Cs(s.g),s.b=Cs(s.b)),this.spaces[r].primaries!==this.spaces[o].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[o].fromXYZ)),this.spaces[o].transfer===kt&&(s.r=Mo(s.r),s.g=Mo(s.g),s.b=Mo(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Us?va:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,o){return s.copy(this.spaces[o].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[ya]:{primaries:e,whitePoint:i,transfer:va,toXYZ:Km,fromXYZ:jm,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:_i},outputColorSpaceConfig:{drawingBufferColorSpace:_i}},[_i]:{primaries:e,whitePoint:i,transfer:kt,toXYZ:Km,fromXYZ:jm,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:_i}}}),n}var At=tv();function Cs(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function Mo(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}var lo,yc=class{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let i;if(e instanceof HTMLCanvasElement)i=e;else{lo===void 0&&(lo=Ma("canvas")),lo.width=e.width,lo.height=e.height;let s=lo.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),i=lo}return i.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=Ma("canvas");t.width=e.width,t.height=e.height;let i=t.getContext("2d");i.drawImage(e,0,0,e.width,e.height);let s=i.getImageData(0,0,e.width,e.height),r=s.data;for(let o=0;o<r.length;o++)r[o]=Cs(r[o]/255)*255;return i.putImageData(s,0,0),t}else if(e.data){let t=e.data.slice(0);for(let i=0;i<t.length;i++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[i]=Math.floor(Cs(t[i]/255)*255):t[i]=Cs(t[i]);return{data:t,width:e.width,height:e.height}}else return et("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},nv=0,To=class{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:nv++}),this.uuid=Oo(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){let t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let i={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let o=0,a=s.length;o<a;o++)s[o].isDataTexture?r.push(ef(s[o].image)):r.push(ef(s[o]))}else r=ef(s);i.url=r}return t||(e.images[this.uuid]=i),i}};function ef(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?yc.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(et("Texture: Unable to serialize Texture."),{})}var iv=0,tf=new ee,ti=class n extends Gi{constructor(e=n.DEFAULT_IMAGE,t=n.DEFAULT_MAPPING,i=as,s=as,r=Qn,o=Ds,a=Yi,c=bi,l=n.DEFAULT_ANISOTROPY,h=Us){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:iv++}),this.uuid=Oo(),this.name="",this.source=new To(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=i,this.wrapT=s,this.magFilter=r,this.minFilter=o,this.anisotropy=l,this.format=a,this.internalFormat=null,this.type=c,this.offset=new ft(0,0),this.repeat=new ft(1,1),this.center=new ft(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new lt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(tf).x}get height(){return this.source.getSize(tf).y}get depth(){return this.source.getSize(tf).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(let t in e){let i=e[t];if(i===void 0){et(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){et(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&i&&s.isVector2&&i.isVector2||s&&i&&s.isVector3&&i.isVector3||s&&i&&s.isMatrix3&&i.isMatrix3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),t||(e.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==zf)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case gc:e.x=e.x-Math.floor(e.x);break;case as:e.x=e.x<0?0:1;break;case _c:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case gc:e.y=e.y-Math.floor(e.y);break;case as:e.y=e.y<0?0:1;break;case _c:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};ti.DEFAULT_IMAGE=null;ti.DEFAULT_MAPPING=zf;ti.DEFAULT_ANISOTROPY=1;var ud=class ud{constructor(e=0,t=0,i=0,s=1){this.x=e,this.y=t,this.z=i,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,i,s){return this.x=e,this.y=t,this.z=i,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=this.w,o=e.elements;return this.x=o[0]*t+o[4]*i+o[8]*s+o[12]*r,this.y=o[1]*t+o[5]*i+o[9]*s+o[13]*r,this.z=o[2]*t+o[6]*i+o[10]*s+o[14]*r,this.w=o[3]*t+o[7]*i+o[11]*s+o[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,i,s,r,c=e.elements,l=c[0],h=c[4],f=c[8],u=c[1],p=c[5],g=c[9],b=c[2],d=c[6],m=c[10];if(Math.abs(h-u)<.01&&Math.abs(f-b)<.01&&Math.abs(g-d)<.01){if(Math.abs(h+u)<.1&&Math.abs(f+b)<.1&&Math.abs(g+d)<.1&&Math.abs(l+p+m-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let C=(l+1)/2,S=(p+1)/2,P=(m+1)/2,T=(h+u)/4,_=(f+b)/4,R=(g+d)/4;return C>S&&C>P?C<.01?(i=0,s=.707106781,r=.707106781):(i=Math.sqrt(C),s=T/i,r=_/i):S>P?S<.01?(i=.707106781,s=0,r=.707106781):(s=Math.sqrt(S),i=T/s,r=R/s):P<.01?(i=.707106781,s=.707106781,r=0):(r=Math.sqrt(P),i=_/r,s=R/r),this.set(i,s,r,t),this}let v=Math.sqrt((d-g)*(d-g)+(f-b)*(f-b)+(u-h)*(u-h));return Math.abs(v)<.001&&(v=1),this.x=(d-g)/v,this.y=(f-b)/v,this.z=(u-h)/v,this.w=Math.acos((l+p+m-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=Mt(this.x,e.x,t.x),this.y=Mt(this.y,e.y,t.y),this.z=Mt(this.z,e.z,t.z),this.w=Mt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=Mt(this.x,e,t),this.y=Mt(this.y,e,t),this.z=Mt(this.z,e,t),this.w=Mt(this.w,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(Mt(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this.w=e.w+(t.w-e.w)*i,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};ud.prototype.isVector4=!0;var rn=ud,vc=class extends Gi{constructor(e=1,t=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Qn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=i.depth,this.scissor=new rn(0,0,e,t),this.scissorTest=!1,this.viewport=new rn(0,0,e,t),this.textures=[];let s=i.count;for(let r=0;r<s;r++)this.textures[r]=new ti({width:e,height:t,depth:i.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(e={}){let t={minFilter:Qn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,i=1){if(this.width!==e||this.height!==t||this.depth!==i){this.width=e,this.height=t,this.depth=i;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=i,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,i=e.textures.length;t<i;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;let s=Object.assign({},e.textures[t].image);this.textures[t].source=new To(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){let t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},Si=class extends vc{constructor(e=1,t=1,i={}){super(e,t,i),this.isWebGLRenderTarget=!0}},ba=class extends ti{constructor(e=null,t=1,i=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Bn,this.minFilter=Bn,this.wrapR=as,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var Sc=class extends ti{constructor(e=null,t=1,i=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Bn,this.minFilter=Bn,this.wrapR=as,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}};var Gc=class Gc{constructor(e,t,i,s,r,o,a,c,l,h,f,u,p,g,b,d){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,c,l,h,f,u,p,g,b,d)}set(e,t,i,s,r,o,a,c,l,h,f,u,p,g,b,d){let m=this.elements;return m[0]=e,m[4]=t,m[8]=i,m[12]=s,m[1]=r,m[5]=o,m[9]=a,m[13]=c,m[2]=l,m[6]=h,m[10]=f,m[14]=u,m[3]=p,m[7]=g,m[11]=b,m[15]=d,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Gc().fromArray(this.elements)}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],t[9]=i[9],t[10]=i[10],t[11]=i[11],t[12]=i[12],t[13]=i[13],t[14]=i[14],t[15]=i[15],this}copyPosition(e){let t=this.elements,i=e.elements;return t[12]=i[12],t[13]=i[13],t[14]=i[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,i){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),i.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(e,t,i){return this.set(e.x,t.x,i.x,0,e.y,t.y,i.y,0,e.z,t.z,i.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();let t=this.elements,i=e.elements,s=1/co.setFromMatrixColumn(e,0).length(),r=1/co.setFromMatrixColumn(e,1).length(),o=1/co.setFromMatrixColumn(e,2).length();return t[0]=i[0]*s,t[1]=i[1]*s,t[2]=i[2]*s,t[3]=0,t[4]=i[4]*r,t[5]=i[5]*r,t[6]=i[6]*r,t[7]=0,t[8]=i[8]*o,t[9]=i[9]*o,t[10]=i[10]*o,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,i=e.x,s=e.y,r=e.z,o=Math.cos(i),a=Math.sin(i),c=Math.cos(s),l=Math.sin(s),h=Math.cos(r),f=Math.sin(r);if(e.order==="XYZ"){let u=o*h,p=o*f,g=a*h,b=a*f;t[0]=c*h,t[4]=-c*f,t[8]=l,t[1]=p+g*l,t[5]=u-b*l,t[9]=-a*c,t[2]=b-u*l,t[6]=g+p*l,t[10]=o*c}else if(e.order==="YXZ"){let u=c*h,p=c*f,g=l*h,b=l*f;t[0]=u+b*a,t[4]=g*a-p,t[8]=o*l,t[1]=o*f,t[5]=o*h,t[9]=-a,t[2]=p*a-g,t[6]=b+u*a,t[10]=o*c}else if(e.order==="ZXY"){let u=c*h,p=c*f,g=l*h,b=l*f;t[0]=u-b*a,t[4]=-o*f,t[8]=g+p*a,t[1]=p+g*a,t[5]=o*h,t[9]=b-u*a,t[2]=-o*l,t[6]=a,t[10]=o*c}else if(e.order==="ZYX"){let u=o*h,p=o*f,g=a*h,b=a*f;t[0]=c*h,t[4]=g*l-p,t[8]=u*l+b,t[1]=c*f,t[5]=b*l+u,t[9]=p*l-g,t[2]=-l,t[6]=a*c,t[10]=o*c}else if(e.order==="YZX"){let u=o*c,p=o*l,g=a*c,b=a*l;t[0]=c*h,t[4]=b-u*f,t[8]=g*f+p,t[1]=f,t[5]=o*h,t[9]=-a*h,t[2]=-l*h,t[6]=p*f+g,t[10]=u-b*f}else if(e.order==="XZY"){let u=o*c,p=o*l,g=a*c,b=a*l;t[0]=c*h,t[4]=-f,t[8]=l*h,t[1]=u*f+b,t[5]=o*h,t[9]=p*f-g,t[2]=g*f-p,t[6]=a*h,t[10]=b*f+u}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(sv,e,rv)}lookAt(e,t,i){let s=this.elements;return mi.subVectors(e,t),mi.lengthSq()===0&&(mi.z=1),mi.normalize(),qs.crossVectors(i,mi),qs.lengthSq()===0&&(Math.abs(i.z)===1?mi.x+=1e-4:mi.z+=1e-4,mi.normalize(),qs.crossVectors(i,mi)),qs.normalize(),Ol.crossVectors(mi,qs),s[0]=qs.x,s[4]=Ol.x,s[8]=mi.x,s[1]=qs.y,s[5]=Ol.y,s[9]=mi.y,s[2]=qs.z,s[6]=Ol.z,s[10]=mi.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[4],c=i[8],l=i[12],h=i[1],f=i[5],u=i[9],p=i[13],g=i[2],b=i[6],d=i[10],m=i[14],v=i[3],C=i[7],S=i[11],P=i[15],T=s[0],_=s[4],R=s[8],W=s[12],O=s[1],L=s[5],G=s[9],X=s[13],y=s[2],U=s[6],D=s[10],A=s[14],z=s[3],B=s[7],H=s[11],$=s[15];return r[0]=o*T+a*O+c*y+l*z,r[4]=o*_+a*L+c*U+l*B,r[8]=o*R+a*G+c*D+l*H,r[12]=o*W+a*X+c*A+l*$,r[1]=h*T+f*O+u*y+p*z,r[5]=h*_+f*L+u*U+p*B,r[9]=h*R+f*G+u*D+p*H,r[13]=h*W+f*X+u*A+p*$,r[2]=g*T+b*O+d*y+m*z,r[6]=g*_+b*L+d*U+m*B,r[10]=g*R+b*G+d*D+m*H,r[14]=g*W+b*X+d*A+m*$,r[3]=v*T+C*O+S*y+P*z,r[7]=v*_+C*L+S*U+P*B,r[11]=v*R+C*G+S*D+P*H,r[15]=v*W+C*X+S*A+P*$,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[12],o=e[1],a=e[5],c=e[9],l=e[13],h=e[2],f=e[6],u=e[10],p=e[14],g=e[3],b=e[7],d=e[11],m=e[15],v=c*p-l*u,C=a*p-l*f,S=a*u-c*f,P=o*p-l*h,T=o*u-c*h,_=o*f-a*h;return t*(b*v-d*C+m*S)-i*(g*v-d*P+m*T)+s*(g*C-b*P+m*_)-r*(g*S-b*T+d*_)}determinantAffine(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[1],o=e[5],a=e[9],c=e[2],l=e[6],h=e[10];return t*(o*h-a*l)-i*(r*h-a*c)+s*(r*l-o*c)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,i){let s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=i),this}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],c=e[6],l=e[7],h=e[8],f=e[9],u=e[10],p=e[11],g=e[12],b=e[13],d=e[14],m=e[15],v=t*a-i*o,C=t*c-s*o,S=t*l-r*o,P=i*c-s*a,T=i*l-r*a,_=s*l-r*c,R=h*b-f*g,W=h*d-u*g,O=h*m-p*g,L=f*d-u*b,G=f*m-p*b,X=u*m-p*d,y=v*X-C*G+S*L+P*O-T*W+_*R;if(y===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let U=1/y;return e[0]=(a*X-c*G+l*L)*U,e[1]=(s*G-i*X-r*L)*U,e[2]=(b*_-d*T+m*P)*U,e[3]=(u*T-f*_-p*P)*U,e[4]=(c*O-o*X-l*W)*U,e[5]=(t*X-s*O+r*W)*U,e[6]=(d*S-g*_-m*C)*U,e[7]=(h*_-u*S+p*C)*U,e[8]=(o*G-a*O+l*R)*U,e[9]=(i*O-t*G-r*R)*U,e[10]=(g*T-b*S+m*v)*U,e[11]=(f*S-h*T-p*v)*U,e[12]=(a*W-o*L-c*R)*U,e[13]=(t*L-i*W+s*R)*U,e[14]=(b*C-g*P-d*v)*U,e[15]=(h*P-f*C+u*v)*U,this}scale(e){let t=this.elements,i=e.x,s=e.y,r=e.z;return t[0]*=i,t[4]*=s,t[8]*=r,t[1]*=i,t[5]*=s,t[9]*=r,t[2]*=i,t[6]*=s,t[10]*=r,t[3]*=i,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],i=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,i,s))}makeTranslation(e,t,i){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,i,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),i=Math.sin(e);return this.set(1,0,0,0,0,t,-i,0,0,i,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,0,i,0,0,1,0,0,-i,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,0,i,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let i=Math.cos(t),s=Math.sin(t),r=1-i,o=e.x,a=e.y,c=e.z,l=r*o,h=r*a;return this.set(l*o+i,l*a-s*c,l*c+s*a,0,l*a+s*c,h*a+i,h*c-s*o,0,l*c-s*a,h*c+s*o,r*c*c+i,0,0,0,0,1),this}makeScale(e,t,i){return this.set(e,0,0,0,0,t,0,0,0,0,i,0,0,0,0,1),this}makeShear(e,t,i,s,r,o){return this.set(1,i,r,0,e,1,o,0,t,s,1,0,0,0,0,1),this}compose(e,t,i){let s=this.elements,r=t._x,o=t._y,a=t._z,c=t._w,l=r+r,h=o+o,f=a+a,u=r*l,p=r*h,g=r*f,b=o*h,d=o*f,m=a*f,v=c*l,C=c*h,S=c*f,P=i.x,T=i.y,_=i.z;return s[0]=(1-(b+m))*P,s[1]=(p+S)*P,s[2]=(g-C)*P,s[3]=0,s[4]=(p-S)*T,s[5]=(1-(u+m))*T,s[6]=(d+v)*T,s[7]=0,s[8]=(g+C)*_,s[9]=(d-v)*_,s[10]=(1-(u+b))*_,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,i){let s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];let r=this.determinantAffine();if(r===0)return i.set(1,1,1),t.identity(),this;let o=co.set(s[0],s[1],s[2]).length(),a=co.set(s[4],s[5],s[6]).length(),c=co.set(s[8],s[9],s[10]).length();r<0&&(o=-o),zi.copy(this);let l=1/o,h=1/a,f=1/c;return zi.elements[0]*=l,zi.elements[1]*=l,zi.elements[2]*=l,zi.elements[4]*=h,zi.elements[5]*=h,zi.elements[6]*=h,zi.elements[8]*=f,zi.elements[9]*=f,zi.elements[10]*=f,t.setFromRotationMatrix(zi),i.x=o,i.y=a,i.z=c,this}makePerspective(e,t,i,s,r,o,a=Li,c=!1){let l=this.elements,h=2*r/(t-e),f=2*r/(i-s),u=(t+e)/(t-e),p=(i+s)/(i-s),g,b;if(c)g=r/(o-r),b=o*r/(o-r);else if(a===Li)g=-(o+r)/(o-r),b=-2*o*r/(o-r);else if(a===Sa)g=-o/(o-r),b=-o*r/(o-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+a);return l[0]=h,l[4]=0,l[8]=u,l[12]=0,l[1]=0,l[5]=f,l[9]=p,l[13]=0,l[2]=0,l[6]=0,l[10]=g,l[14]=b,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(e,t,i,s,r,o,a=Li,c=!1){let l=this.elements,h=2/(t-e),f=2/(i-s),u=-(t+e)/(t-e),p=-(i+s)/(i-s),g,b;if(c)g=1/(o-r),b=o/(o-r);else if(a===Li)g=-2/(o-r),b=-(o+r)/(o-r);else if(a===Sa)g=-1/(o-r),b=-r/(o-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+a);return l[0]=h,l[4]=0,l[8]=0,l[12]=u,l[1]=0,l[5]=f,l[9]=0,l[13]=p,l[2]=0,l[6]=0,l[10]=g,l[14]=b,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<16;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<16;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e[t+9]=i[9],e[t+10]=i[10],e[t+11]=i[11],e[t+12]=i[12],e[t+13]=i[13],e[t+14]=i[14],e[t+15]=i[15],e}};Gc.prototype.isMatrix4=!0;var nn=Gc,co=new ee,zi=new nn,sv=new ee(0,0,0),rv=new ee(1,1,1),qs=new ee,Ol=new ee,mi=new ee,Qm=new nn,eg=new vi,js=class n{constructor(e=0,t=0,i=0,s=n.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=i,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,i,s=this._order){return this._x=e,this._y=t,this._z=i,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,i=!0){let s=e.elements,r=s[0],o=s[4],a=s[8],c=s[1],l=s[5],h=s[9],f=s[2],u=s[6],p=s[10];switch(t){case"XYZ":this._y=Math.asin(Mt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(-h,p),this._z=Math.atan2(-o,r)):(this._x=Math.atan2(u,l),this._z=0);break;case"YXZ":this._x=Math.asin(-Mt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(a,p),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-f,r),this._z=0);break;case"ZXY":this._x=Math.asin(Mt(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(-f,p),this._z=Math.atan2(-o,l)):(this._y=0,this._z=Math.atan2(c,r));break;case"ZYX":this._y=Math.asin(-Mt(f,-1,1)),Math.abs(f)<.9999999?(this._x=Math.atan2(u,p),this._z=Math.atan2(c,r)):(this._x=0,this._z=Math.atan2(-o,l));break;case"YZX":this._z=Math.asin(Mt(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-h,l),this._y=Math.atan2(-f,r)):(this._x=0,this._y=Math.atan2(a,p));break;case"XZY":this._z=Math.asin(-Mt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(u,l),this._y=Math.atan2(a,r)):(this._x=Math.atan2(-h,p),this._y=0);break;default:et("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,i===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,i){return Qm.makeRotationFromQuaternion(e),this.setFromRotationMatrix(Qm,t,i)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return eg.setFromEuler(this),this.setFromQuaternion(eg,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};js.DEFAULT_ORDER="XYZ";var wa=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},ov=0,tg=new ee,ho=new vi,ws=new nn,Bl=new ee,ha=new ee,av=new ee,lv=new vi,ng=new ee(1,0,0),ig=new ee(0,1,0),sg=new ee(0,0,1),rg={type:"added"},cv={type:"removed"},uo={type:"childadded",child:null},nf={type:"childremoved",child:null},ni=class n extends Gi{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:ov++}),this.uuid=Oo(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=n.DEFAULT_UP.clone();let e=new ee,t=new js,i=new vi,s=new ee(1,1,1);function r(){i.setFromEuler(t,!1)}function o(){t.setFromQuaternion(i,void 0,!1)}t._onChange(r),i._onChange(o),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new nn},normalMatrix:{value:new lt}}),this.matrix=new nn,this.matrixWorld=new nn,this.matrixAutoUpdate=n.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=n.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new wa,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return ho.setFromAxisAngle(e,t),this.quaternion.multiply(ho),this}rotateOnWorldAxis(e,t){return ho.setFromAxisAngle(e,t),this.quaternion.premultiply(ho),this}rotateX(e){return this.rotateOnAxis(ng,e)}rotateY(e){return this.rotateOnAxis(ig,e)}rotateZ(e){return this.rotateOnAxis(sg,e)}translateOnAxis(e,t){return tg.copy(e).applyQuaternion(this.quaternion),this.position.add(tg.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(ng,e)}translateY(e){return this.translateOnAxis(ig,e)}translateZ(e){return this.translateOnAxis(sg,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(ws.copy(this.matrixWorld).invert())}lookAt(e,t,i){e.isVector3?Bl.copy(e):Bl.set(e,t,i);let s=this.parent;this.updateWorldMatrix(!0,!1),ha.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?ws.lookAt(ha,Bl,this.up):ws.lookAt(Bl,ha,this.up),this.quaternion.setFromRotationMatrix(ws),s&&(ws.extractRotation(s.matrixWorld),ho.setFromRotationMatrix(ws),this.quaternion.premultiply(ho.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(at("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(rg),uo.child=e,this.dispatchEvent(uo),uo.child=null):at("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(cv),nf.child=e,this.dispatchEvent(nf),nf.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),ws.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),ws.multiply(e.parent.matrixWorld)),e.applyMatrix4(ws),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(rg),uo.child=e,this.dispatchEvent(uo),uo.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let i=0,s=this.children.length;i<s;i++){let o=this.children[i].getObjectByProperty(e,t);if(o!==void 0)return o}}getObjectsByProperty(e,t,i=[]){this[e]===t&&i.push(this);let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].getObjectsByProperty(e,t,i);return i}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ha,e,av),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(ha,lv,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let e=this.pivot;if(e!==null){let t=e.x,i=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*i-r[8]*s,r[13]+=i-r[1]*t-r[5]*i-r[9]*s,r[14]+=s-r[2]*t-r[6]*i-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].updateMatrixWorld(e)}updateWorldMatrix(e,t,i=!1){let s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),t===!0){let r=this.children;for(let o=0,a=r.length;o<a;o++)r[o].updateWorldMatrix(!1,!0,i)}}toJSON(e){let t=e===void 0||typeof e=="string",i={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(a=>({...a,boundingBox:a.boundingBox?a.boundingBox.toJSON():void 0,boundingSphere:a.boundingSphere?a.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(a=>({...a})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(a,c){return a[c.uuid]===void 0&&(a[c.uuid]=c.toJSON(e)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);let a=this.geometry.parameters;if(a!==void 0&&a.shapes!==void 0){let c=a.shapes;if(Array.isArray(c))for(let l=0,h=c.length;l<h;l++){let f=c[l];r(e.shapes,f)}else r(e.shapes,c)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let a=[];for(let c=0,l=this.material.length;c<l;c++)a.push(r(e.materials,this.material[c]));s.material=a}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let a=0;a<this.children.length;a++)s.children.push(this.children[a].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let a=0;a<this.animations.length;a++){let c=this.animations[a];s.animations.push(r(e.animations,c))}}if(t){let a=o(e.geometries),c=o(e.materials),l=o(e.textures),h=o(e.images),f=o(e.shapes),u=o(e.skeletons),p=o(e.animations),g=o(e.nodes);a.length>0&&(i.geometries=a),c.length>0&&(i.materials=c),l.length>0&&(i.textures=l),h.length>0&&(i.images=h),f.length>0&&(i.shapes=f),u.length>0&&(i.skeletons=u),p.length>0&&(i.animations=p),g.length>0&&(i.nodes=g)}return i.object=s,i;function o(a){let c=[];for(let l in a){let h=a[l];delete h.metadata,c.push(h)}return c}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let i=0;i<e.children.length;i++){let s=e.children[i];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};ni.DEFAULT_UP=new ee(0,1,0);ni.DEFAULT_MATRIX_AUTO_UPDATE=!0;ni.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var Tr=class extends ni{constructor(){super(),this.isGroup=!0,this.type="Group"}},hv={type:"move"},Ao=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Tr,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Tr,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new ee,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new ee),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Tr,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new ee,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new ee,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let i of e.hand.values())this._getHandJoint(t,i)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,i){let s=null,r=null,o=null,a=this._targetRay,c=this._grip,l=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(l&&e.hand){o=!0;for(let b of e.hand.values()){let d=t.getJointPose(b,i),m=this._getHandJoint(l,b);d!==null&&(m.matrix.fromArray(d.transform.matrix),m.matrix.decompose(m.position,m.quaternion,m.scale),m.matrixWorldNeedsUpdate=!0,m.jointRadius=d.radius),m.visible=d!==null}let h=l.joints["index-finger-tip"],f=l.joints["thumb-tip"],u=h.position.distanceTo(f.position),p=.02,g=.005;l.inputState.pinching&&u>p+g?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!l.inputState.pinching&&u<=p-g&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else c!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,i),r!==null&&(c.matrix.fromArray(r.transform.matrix),c.matrix.decompose(c.position,c.quaternion,c.scale),c.matrixWorldNeedsUpdate=!0,r.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(r.linearVelocity)):c.hasLinearVelocity=!1,r.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(r.angularVelocity)):c.hasAngularVelocity=!1,c.eventsEnabled&&c.dispatchEvent({type:"gripUpdated",data:e,target:this})));a!==null&&(s=t.getPose(e.targetRaySpace,i),s===null&&r!==null&&(s=r),s!==null&&(a.matrix.fromArray(s.transform.matrix),a.matrix.decompose(a.position,a.quaternion,a.scale),a.matrixWorldNeedsUpdate=!0,s.linearVelocity?(a.hasLinearVelocity=!0,a.linearVelocity.copy(s.linearVelocity)):a.hasLinearVelocity=!1,s.angularVelocity?(a.hasAngularVelocity=!0,a.angularVelocity.copy(s.angularVelocity)):a.hasAngularVelocity=!1,this.dispatchEvent(hv)))}return a!==null&&(a.visible=s!==null),c!==null&&(c.visible=r!==null),l!==null&&(l.visible=o!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let i=new Tr;i.matrixAutoUpdate=!1,i.visible=!1,e.joints[t.jointName]=i,e.add(i)}return e.joints[t.jointName]}},a0={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Ys={h:0,s:0,l:0},kl={h:0,s:0,l:0};function sf(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}var _t=class{constructor(e,t,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,i)}set(e,t,i){if(t===void 0&&i===void 0){let s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,i);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=_i){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,At.colorSpaceToWorking(this,t),this}setRGB(e,t,i,s=At.workingColorSpace){return this.r=e,this.g=t,this.b=i,At.colorSpaceToWorking(this,s),this}setHSL(e,t,i,s=At.workingColorSpace){if(e=ed(e,1),t=Mt(t,0,1),i=Mt(i,0,1),t===0)this.r=this.g=this.b=i;else{let r=i<=.5?i*(1+t):i+t-i*t,o=2*i-r;this.r=sf(o,r,e+1/3),this.g=sf(o,r,e),this.b=sf(o,r,e-1/3)}return At.colorSpaceToWorking(this,s),this}setStyle(e,t=_i){function i(r){r!==void 0&&parseFloat(r)<1&&et("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r,o=s[1],a=s[2];switch(o){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:et("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){let r=s[1],o=r.length;if(o===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(o===6)return this.setHex(parseInt(r,16),t);et("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=_i){let i=a0[e.toLowerCase()];return i!==void 0?this.setHex(i,t):et("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=Cs(e.r),this.g=Cs(e.g),this.b=Cs(e.b),this}copyLinearToSRGB(e){return this.r=Mo(e.r),this.g=Mo(e.g),this.b=Mo(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=_i){return At.workingToColorSpace(Gn.copy(this),e),Math.round(Mt(Gn.r*255,0,255))*65536+Math.round(Mt(Gn.g*255,0,255))*256+Math.round(Mt(Gn.b*255,0,255))}getHexString(e=_i){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=At.workingColorSpace){At.workingToColorSpace(Gn.copy(this),t);let i=Gn.r,s=Gn.g,r=Gn.b,o=Math.max(i,s,r),a=Math.min(i,s,r),c,l,h=(a+o)/2;if(a===o)c=0,l=0;else{let f=o-a;switch(l=h<=.5?f/(o+a):f/(2-o-a),o){case i:c=(s-r)/f+(s<r?6:0);break;case s:c=(r-i)/f+2;break;case r:c=(i-s)/f+4;break}c/=6}return e.h=c,e.s=l,e.l=h,e}getRGB(e,t=At.workingColorSpace){return At.workingToColorSpace(Gn.copy(this),t),e.r=Gn.r,e.g=Gn.g,e.b=Gn.b,e}getStyle(e=_i){At.workingToColorSpace(Gn.copy(this),e);let t=Gn.r,i=Gn.g,s=Gn.b;return e!==_i?`color(${e} ${t.toFixed(3)} ${i.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(i*255)},${Math.round(s*255)})`}offsetHSL(e,t,i){return this.getHSL(Ys),this.setHSL(Ys.h+e,Ys.s+t,Ys.l+i)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,i){return this.r=e.r+(t.r-e.r)*i,this.g=e.g+(t.g-e.g)*i,this.b=e.b+(t.b-e.b)*i,this}lerpHSL(e,t){this.getHSL(Ys),e.getHSL(kl);let i=_a(Ys.h,kl.h,t),s=_a(Ys.s,kl.s,t),r=_a(Ys.l,kl.l,t);return this.setHSL(i,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,i=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*i+r[6]*s,this.g=r[1]*t+r[4]*i+r[7]*s,this.b=r[2]*t+r[5]*i+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},Gn=new _t;_t.NAMES=a0;var Ea=class extends ni{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new js,this.environmentIntensity=1,this.environmentRotation=new js,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}},Vi=new ee,Es=new ee,rf=new ee,Ts=new ee,fo=new ee,po=new ee,og=new ee,of=new ee,af=new ee,lf=new ee,cf=new rn,hf=new rn,uf=new rn,Ks=class n{constructor(e=new ee,t=new ee,i=new ee){this.a=e,this.b=t,this.c=i}static getNormal(e,t,i,s){s.subVectors(i,t),Vi.subVectors(e,t),s.cross(Vi);let r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,i,s,r){Vi.subVectors(s,t),Es.subVectors(i,t),rf.subVectors(e,t);let o=Vi.dot(Vi),a=Vi.dot(Es),c=Vi.dot(rf),l=Es.dot(Es),h=Es.dot(rf),f=o*l-a*a;if(f===0)return r.set(0,0,0),null;let u=1/f,p=(l*c-a*h)*u,g=(o*h-a*c)*u;return r.set(1-p-g,g,p)}static containsPoint(e,t,i,s){return this.getBarycoord(e,t,i,s,Ts)===null?!1:Ts.x>=0&&Ts.y>=0&&Ts.x+Ts.y<=1}static getInterpolation(e,t,i,s,r,o,a,c){return this.getBarycoord(e,t,i,s,Ts)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(r,Ts.x),c.addScaledVector(o,Ts.y),c.addScaledVector(a,Ts.z),c)}static getInterpolatedAttribute(e,t,i,s,r,o){return cf.setScalar(0),hf.setScalar(0),uf.setScalar(0),cf.fromBufferAttribute(e,t),hf.fromBufferAttribute(e,i),uf.fromBufferAttribute(e,s),o.setScalar(0),o.addScaledVector(cf,r.x),o.addScaledVector(hf,r.y),o.addScaledVector(uf,r.z),o}static isFrontFacing(e,t,i,s){return Vi.subVectors(i,t),Es.subVectors(e,t),Vi.cross(Es).dot(s)<0}set(e,t,i){return this.a.copy(e),this.b.copy(t),this.c.copy(i),this}setFromPointsAndIndices(e,t,i,s){return this.a.copy(e[t]),this.b.copy(e[i]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,i,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,i),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Vi.subVectors(this.c,this.b),Es.subVectors(this.a,this.b),Vi.cross(Es).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return n.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return n.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,i,s,r){return n.getInterpolation(e,this.a,this.b,this.c,t,i,s,r)}containsPoint(e){return n.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return n.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let i=this.a,s=this.b,r=this.c,o,a;fo.subVectors(s,i),po.subVectors(r,i),of.subVectors(e,i);let c=fo.dot(of),l=po.dot(of);if(c<=0&&l<=0)return t.copy(i);af.subVectors(e,s);let h=fo.dot(af),f=po.dot(af);if(h>=0&&f<=h)return t.copy(s);let u=c*f-h*l;if(u<=0&&c>=0&&h<=0&&c-h>0)return o=c/(c-h),t.copy(i).addScaledVector(fo,o);lf.subVectors(e,r);let p=fo.dot(lf),g=po.dot(lf);if(g>=0&&p<=g)return t.copy(r);let b=p*l-c*g;if(b<=0&&l>=0&&g<=0)return a=l/(l-g),t.copy(i).addScaledVector(po,a);let d=h*g-p*f;if(d<=0&&f-h>=0&&p-g>=0)return og.subVectors(r,s),a=(f-h)/(f-h+(p-g)),t.copy(s).addScaledVector(og,a);let m=1/(d+b+u);return o=b*m,a=u*m,t.copy(i).addScaledVector(fo,o).addScaledVector(po,a)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},Qs=class{constructor(e=new ee(1/0,1/0,1/0),t=new ee(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t+=3)this.expandByPoint(Hi.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,i=e.count;t<i;t++)this.expandByPoint(Hi.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let i=Hi.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(i),this.max.copy(e).add(i),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let i=e.geometry;if(i!==void 0){let r=i.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let o=0,a=r.count;o<a;o++)e.isMesh===!0?e.getVertexPosition(o,Hi):Hi.fromBufferAttribute(r,o),Hi.applyMatrix4(e.matrixWorld),this.expandByPoint(Hi);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),zl.copy(e.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),zl.copy(i.boundingBox)),zl.applyMatrix4(e.matrixWorld),this.union(zl)}let s=e.children;for(let r=0,o=s.length;r<o;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Hi),Hi.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,i;return e.normal.x>0?(t=e.normal.x*this.min.x,i=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,i=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,i+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,i+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,i+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,i+=e.normal.z*this.min.z),t<=-e.constant&&i>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(ua),Vl.subVectors(this.max,ua),mo.subVectors(e.a,ua),go.subVectors(e.b,ua),_o.subVectors(e.c,ua),$s.subVectors(go,mo),Zs.subVectors(_o,go),Mr.subVectors(mo,_o);let t=[0,-$s.z,$s.y,0,-Zs.z,Zs.y,0,-Mr.z,Mr.y,$s.z,0,-$s.x,Zs.z,0,-Zs.x,Mr.z,0,-Mr.x,-$s.y,$s.x,0,-Zs.y,Zs.x,0,-Mr.y,Mr.x,0];return!ff(t,mo,go,_o,Vl)||(t=[1,0,0,0,1,0,0,0,1],!ff(t,mo,go,_o,Vl))?!1:(Hl.crossVectors($s,Zs),t=[Hl.x,Hl.y,Hl.z],ff(t,mo,go,_o,Vl))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Hi).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Hi).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(As[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),As[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),As[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),As[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),As[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),As[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),As[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),As[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(As),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}},As=[new ee,new ee,new ee,new ee,new ee,new ee,new ee,new ee],Hi=new ee,zl=new Qs,mo=new ee,go=new ee,_o=new ee,$s=new ee,Zs=new ee,Mr=new ee,ua=new ee,Vl=new ee,Hl=new ee,br=new ee;function ff(n,e,t,i,s){for(let r=0,o=n.length-3;r<=o;r+=3){br.fromArray(n,r);let a=s.x*Math.abs(br.x)+s.y*Math.abs(br.y)+s.z*Math.abs(br.z),c=e.dot(br),l=t.dot(br),h=i.dot(br);if(Math.max(-Math.max(c,l,h),Math.min(c,l,h))>a)return!1}return!0}var Mn=new ee,Gl=new ft,uv=0,yi=class extends Gi{constructor(e,t,i=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:uv++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=i,this.usage=e0,this.updateRanges=[],this.gpuType=Xi,this.version=0,this._normalizationScale=e!==void 0?nd(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,i){e*=this.itemSize,i*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[i+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,i=this.count;t<i;t++)Gl.fromBufferAttribute(this,t),Gl.applyMatrix3(e),this.setXY(t,Gl.x,Gl.y);else if(this.itemSize===3)for(let t=0,i=this.count;t<i;t++)Mn.fromBufferAttribute(this,t),Mn.applyMatrix3(e),this.setXYZ(t,Mn.x,Mn.y,Mn.z);return this}applyMatrix4(e){for(let t=0,i=this.count;t<i;t++)Mn.fromBufferAttribute(this,t),Mn.applyMatrix4(e),this.setXYZ(t,Mn.x,Mn.y,Mn.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)Mn.fromBufferAttribute(this,t),Mn.applyNormalMatrix(e),this.setXYZ(t,Mn.x,Mn.y,Mn.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)Mn.fromBufferAttribute(this,t),Mn.transformDirection(e),this.setXYZ(t,Mn.x,Mn.y,Mn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let i=this.array[e*this.itemSize+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.array[e*this.itemSize+t]=i,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,i){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.array[e+0]=t,this.array[e+1]=i,this}setXYZ(e,t,i,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this}setXYZW(e,t,i,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):r0(e,this.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):o0(e,this.array)}};var Ta=class extends yi{constructor(e,t,i){super(new Uint16Array(e),t,i)}};var Aa=class extends yi{constructor(e,t,i){super(new Uint32Array(e),t,i)}};var On=class extends yi{constructor(e,t,i){super(new Float32Array(e),t,i)}},fv=new Qs,fa=new ee,df=new ee,er=class{constructor(e=new ee,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let i=this.center;t!==void 0?i.copy(t):fv.setFromPoints(e).getCenter(i);let s=0;for(let r=0,o=e.length;r<o;r++)s=Math.max(s,i.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let i=this.center.distanceToSquared(e);return t.copy(e),i>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;fa.subVectors(e,this.center);let t=fa.lengthSq();if(t>this.radius*this.radius){let i=Math.sqrt(t),s=(i-this.radius)*.5;this.center.addScaledVector(fa,s/i),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(df.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(fa.copy(e.center).add(df)),this.expandByPoint(fa.copy(e.center).sub(df))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}},dv=0,Ii=new nn,pf=new ni,xo=new ee,gi=new Qs,da=new Qs,Fn=new ee,ii=class n extends Gi{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:dv++}),this.uuid=Oo(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(By(e)?Aa:Ta)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,i=0){this.groups.push({start:e,count:t,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let i=this.attributes.normal;if(i!==void 0){let r=new lt().getNormalMatrix(e);i.applyNormalMatrix(r),i.needsUpdate=!0}let s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return Ii.makeRotationFromQuaternion(e),this.applyMatrix4(Ii),this}rotateX(e){return Ii.makeRotationX(e),this.applyMatrix4(Ii),this}rotateY(e){return Ii.makeRotationY(e),this.applyMatrix4(Ii),this}rotateZ(e){return Ii.makeRotationZ(e),this.applyMatrix4(Ii),this}translate(e,t,i){return Ii.makeTranslation(e,t,i),this.applyMatrix4(Ii),this}scale(e,t,i){return Ii.makeScale(e,t,i),this.applyMatrix4(Ii),this}lookAt(e){return pf.lookAt(e),pf.updateMatrix(),this.applyMatrix4(pf.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(xo).negate(),this.translate(xo.x,xo.y,xo.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let i=[];for(let s=0,r=e.length;s<r;s++){let o=e[s];i.push(o.x,o.y,o.z||0)}this.setAttribute("position",new On(i,3))}else{let i=Math.min(e.length,t.count);for(let s=0;s<i;s++){let r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&et("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Qs);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){at("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new ee(-1/0,-1/0,-1/0),new ee(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let i=0,s=t.length;i<s;i++){let r=t[i];gi.setFromBufferAttribute(r),this.morphTargetsRelative?(Fn.addVectors(this.boundingBox.min,gi.min),this.boundingBox.expandByPoint(Fn),Fn.addVectors(this.boundingBox.max,gi.max),this.boundingBox.expandByPoint(Fn)):(this.boundingBox.expandByPoint(gi.min),this.boundingBox.expandByPoint(gi.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&at('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new er);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){at("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new ee,1/0);return}if(e){let i=this.boundingSphere.center;if(gi.setFromBufferAttribute(e),t)for(let r=0,o=t.length;r<o;r++){let a=t[r];da.setFromBufferAttribute(a),this.morphTargetsRelative?(Fn.addVectors(gi.min,da.min),gi.expandByPoint(Fn),Fn.addVectors(gi.max,da.max),gi.expandByPoint(Fn)):(gi.expandByPoint(da.min),gi.expandByPoint(da.max))}gi.getCenter(i);let s=0;for(let r=0,o=e.count;r<o;r++)Fn.fromBufferAttribute(e,r),s=Math.max(s,i.distanceToSquared(Fn));if(t)for(let r=0,o=t.length;r<o;r++){let a=t[r],c=this.morphTargetsRelative;for(let l=0,h=a.count;l<h;l++)Fn.fromBufferAttribute(a,l),c&&(xo.fromBufferAttribute(e,l),Fn.add(xo)),s=Math.max(s,i.distanceToSquared(Fn))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&at('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){at("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let i=t.position,s=t.normal,r=t.uv,o=this.getAttribute("tangent");(o===void 0||o.count!==i.count)&&(o=new yi(new Float32Array(4*i.count),4),this.setAttribute("tangent",o));let a=[],c=[],l=new Uint8Array(i.count);for(let W=0;W<i.count;W++)a[W]=new ee,c[W]=new ee;let h=new ee,f=new ee,u=new ee,p=new ft,g=new ft,b=new ft,d=new ee,m=new ee;function v(W,O,L){l[W]=l[O]=l[L]=1,h.fromBufferAttribute(i,W),f.fromBufferAttribute(i,O),u.fromBufferAttribute(i,L),p.fromBufferAttribute(r,W),g.fromBufferAttribute(r,O),b.fromBufferAttribute(r,L),f.sub(h),u.sub(h),g.sub(p),b.sub(p);let G=1/(g.x*b.y-b.x*g.y);isFinite(G)&&(d.copy(f).multiplyScalar(b.y).addScaledVector(u,-g.y).multiplyScalar(G),m.copy(u).multiplyScalar(g.x).addScaledVector(f,-b.x).multiplyScalar(G),a[W].add(d),a[O].add(d),a[L].add(d),c[W].add(m),c[O].add(m),c[L].add(m))}let C=this.groups;C.length===0&&(C=[{start:0,count:e.count}]);for(let W=0,O=C.length;W<O;++W){let L=C[W],G=L.start,X=L.count;for(let y=G,U=G+X;y<U;y+=3)v(e.getX(y+0),e.getX(y+1),e.getX(y+2))}let S=new ee,P=new ee,T=new ee,_=new ee;function R(W){T.fromBufferAttribute(s,W),_.copy(T);let O=a[W];S.copy(O),S.sub(T.multiplyScalar(T.dot(O))).normalize(),P.crossVectors(_,O);let G=P.dot(c[W])<0?-1:1;o.setXYZW(W,S.x,S.y,S.z,G)}for(let W=0,O=i.count;W<O;++W)l[W]&&R(W);this._transformed=!0}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==t.count)i=new yi(new Float32Array(t.count*3),3),this.setAttribute("normal",i);else for(let u=0,p=i.count;u<p;u++)i.setXYZ(u,0,0,0);let s=new ee,r=new ee,o=new ee,a=new ee,c=new ee,l=new ee,h=new ee,f=new ee;if(e)for(let u=0,p=e.count;u<p;u+=3){let g=e.getX(u+0),b=e.getX(u+1),d=e.getX(u+2);s.fromBufferAttribute(t,g),r.fromBufferAttribute(t,b),o.fromBufferAttribute(t,d),h.subVectors(o,r),f.subVectors(s,r),h.cross(f),a.fromBufferAttribute(i,g),c.fromBufferAttribute(i,b),l.fromBufferAttribute(i,d),a.add(h),c.add(h),l.add(h),i.setXYZ(g,a.x,a.y,a.z),i.setXYZ(b,c.x,c.y,c.z),i.setXYZ(d,l.x,l.y,l.z)}else for(let u=0,p=t.count;u<p;u+=3)s.fromBufferAttribute(t,u+0),r.fromBufferAttribute(t,u+1),o.fromBufferAttribute(t,u+2),h.subVectors(o,r),f.subVectors(s,r),h.cross(f),i.setXYZ(u+0,h.x,h.y,h.z),i.setXYZ(u+1,h.x,h.y,h.z),i.setXYZ(u+2,h.x,h.y,h.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,i=e.count;t<i;t++)Fn.fromBufferAttribute(e,t),Fn.normalize(),e.setXYZ(t,Fn.x,Fn.y,Fn.z)}toNonIndexed(){function e(a,c){let l=a.array,h=a.itemSize,f=a.normalized,u=new l.constructor(c.length*h),p=0,g=0;for(let b=0,d=c.length;b<d;b++){a.isInterleavedBufferAttribute?p=c[b]*a.data.stride+a.offset:p=c[b]*h;for(let m=0;m<h;m++)u[g++]=l[p++]}return new yi(u,h,f)}if(this.index===null)return et("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new n,i=this.index.array,s=this.attributes;for(let a in s){let c=s[a],l=e(c,i);t.setAttribute(a,l)}let r=this.morphAttributes;for(let a in r){let c=[],l=r[a];for(let h=0,f=l.length;h<f;h++){let u=l[h],p=e(u,i);c.push(p)}t.morphAttributes[a]=c}t.morphTargetsRelative=this.morphTargetsRelative;let o=this.groups;for(let a=0,c=o.length;a<c;a++){let l=o[a];t.addGroup(l.start,l.count,l.materialIndex)}return t}toJSON(){let e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let c=this.parameters;for(let l in c)c[l]!==void 0&&(e[l]=c[l]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let i=this.attributes;for(let c in i){let l=i[c];e.data.attributes[c]=l.toJSON(e.data)}let s={},r=!1;for(let c in this.morphAttributes){let l=this.morphAttributes[c],h=[];for(let f=0,u=l.length;f<u;f++){let p=l[f];h.push(p.toJSON(e.data))}h.length>0&&(s[c]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);let o=this.groups;o.length>0&&(e.data.groups=JSON.parse(JSON.stringify(o)));let a=this.boundingSphere;return a!==null&&(e.data.boundingSphere=a.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let i=e.index;i!==null&&this.setIndex(i.clone());let s=e.attributes;for(let l in s){let h=s[l];this.setAttribute(l,h.clone(t))}let r=e.morphAttributes;for(let l in r){let h=[],f=r[l];for(let u=0,p=f.length;u<p;u++)h.push(f[u].clone(t));this.morphAttributes[l]=h}this.morphTargetsRelative=e.morphTargetsRelative;let o=e.groups;for(let l=0,h=o.length;l<h;l++){let f=o[l];this.addGroup(f.start,f.count,f.materialIndex)}let a=e.boundingBox;a!==null&&(this.boundingBox=a.clone());let c=e.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}};var mf=new ee,pv=new ee,mv=new lt,xi=class{constructor(e=new ee(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,i,s){return this.normal.set(e,t,i),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,i){let s=mf.subVectors(i,t).cross(pv.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,i=!0){let s=e.delta(mf),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let o=-(e.start.dot(this.normal)+this.constant)/r;return i===!0&&(o<0||o>1)?null:t.copy(e.start).addScaledVector(s,o)}intersectsLine(e){let t=this.distanceToPoint(e.start),i=this.distanceToPoint(e.end);return t<0&&i>0||i<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let i=t||mv.getNormalMatrix(e),s=this.coplanarPoint(mf).applyMatrix4(e),r=this.normal.applyMatrix3(i).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}},gv=0,Is=class extends Gi{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:gv++}),this.uuid=Oo(),this.name="",this.type="Material",this.blending=No,this.side=ar,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Pf,this.blendDst=If,this.blendEquation=Cr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new _t(0,0,0),this.blendAlpha=0,this.depthFunc=bo,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=$g,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=lc,this.stencilZFail=lc,this.stencilZPass=lc,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let i=e[t];if(i===void 0){et(`Material: parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){et(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(i):s&&s.isVector2&&i&&i.isVector2||s&&s.isEuler&&i&&i.isEuler||s&&s.isVector3&&i&&i.isVector3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(e).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(e).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(e).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(e).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(e).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function s(r){let o=[];for(let a in r){let c=r[a];delete c.metadata,o.push(c)}return o}if(t){let r=s(e.textures),o=s(e.images);r.length>0&&(i.textures=r),o.length>0&&(i.images=o)}return i}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new _t().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(i=>new xi().fromJSON(i))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let i=e.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new ft().fromArray(i)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new ft().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,i=null;if(t!==null){let s=t.length;i=new Array(s);for(let r=0;r!==s;++r)i[r]=t[r].clone()}return this.clippingPlanes=i,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}};var Rs=new ee,gf=new ee,Wl=new ee,Xl=new ee,tr=class{constructor(e=new ee,t=new ee(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,Rs)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let i=t.dot(this.direction);return i<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=Rs.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(Rs.copy(this.origin).addScaledVector(this.direction,t),Rs.distanceToSquared(e))}distanceSqToSegment(e,t,i,s){gf.copy(e).add(t).multiplyScalar(.5),Wl.copy(t).sub(e).normalize(),Xl.copy(this.origin).sub(gf);let r=e.distanceTo(t)*.5,o=-this.direction.dot(Wl),a=Xl.dot(this.direction),c=-Xl.dot(Wl),l=Xl.lengthSq(),h=Math.abs(1-o*o),f,u,p,g;if(h>0)if(f=o*c-a,u=o*a-c,g=r*h,f>=0)if(u>=-g)if(u<=g){let b=1/h;f*=b,u*=b,p=f*(f+o*u+2*a)+u*(o*f+u+2*c)+l}else u=r,f=Math.max(0,-(o*u+a)),p=-f*f+u*(u+2*c)+l;else u=-r,f=Math.max(0,-(o*u+a)),p=-f*f+u*(u+2*c)+l;else u<=-g?(f=Math.max(0,-(-o*r+a)),u=f>0?-r:Math.min(Math.max(-r,-c),r),p=-f*f+u*(u+2*c)+l):u<=g?(f=0,u=Math.min(Math.max(-r,-c),r),p=u*(u+2*c)+l):(f=Math.max(0,-(o*r+a)),u=f>0?r:Math.min(Math.max(-r,-c),r),p=-f*f+u*(u+2*c)+l);else u=o>0?-r:r,f=Math.max(0,-(o*u+a)),p=-f*f+u*(u+2*c)+l;return i&&i.copy(this.origin).addScaledVector(this.direction,f),s&&s.copy(gf).addScaledVector(Wl,u),p}intersectSphere(e,t){if(e.radius<0)return null;Rs.subVectors(e.center,this.origin);let i=Rs.dot(this.direction),s=Rs.dot(Rs)-i*i,r=e.radius*e.radius;if(s>r)return null;let o=Math.sqrt(r-s),a=i-o,c=i+o;return c<0?null:a<0?this.at(c,t):this.at(a,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let i=-(this.origin.dot(e.normal)+e.constant)/t;return i>=0?i:null}intersectPlane(e,t){let i=this.distanceToPlane(e);return i===null?null:this.at(i,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let i,s,r,o,a,c,l=1/this.direction.x,h=1/this.direction.y,f=1/this.direction.z,u=this.origin;return l>=0?(i=(e.min.x-u.x)*l,s=(e.max.x-u.x)*l):(i=(e.max.x-u.x)*l,s=(e.min.x-u.x)*l),h>=0?(r=(e.min.y-u.y)*h,o=(e.max.y-u.y)*h):(r=(e.max.y-u.y)*h,o=(e.min.y-u.y)*h),i>o||r>s||((r>i||isNaN(i))&&(i=r),(o<s||isNaN(s))&&(s=o),f>=0?(a=(e.min.z-u.z)*f,c=(e.max.z-u.z)*f):(a=(e.max.z-u.z)*f,c=(e.min.z-u.z)*f),i>c||a>s)||((a>i||i!==i)&&(i=a),(c<s||s!==s)&&(s=c),s<0)?null:this.at(i>=0?i:s,t)}intersectsBox(e){return this.intersectBox(e,Rs)!==null}intersectTriangle(e,t,i,s,r){let o=this.origin,a=this.direction,c=a.x,l=a.y,h=a.z,f=e.x-o.x,u=e.y-o.y,p=e.z-o.z,g=t.x-o.x,b=t.y-o.y,d=t.z-o.z,m=i.x-o.x,v=i.y-o.y,C=i.z-o.z,S=Math.abs(c),P=Math.abs(l),T=Math.abs(h),_,R,W,O,L,G,X,y,U,D,A,z;if(S>=P&&S>=T?(W=c,G=f,U=g,z=m,c>=0?(_=l,R=h,O=u,L=p,X=b,y=d,D=v,A=C):(_=h,R=l,O=p,L=u,X=d,y=b,D=C,A=v)):P>=T?(W=l,G=u,U=b,z=v,l>=0?(_=h,R=c,O=p,L=f,X=d,y=g,D=C,A=m):(_=c,R=h,O=f,L=p,X=g,y=d,D=m,A=C)):(W=h,G=p,U=d,z=C,h>=0?(_=c,R=l,O=f,L=u,X=g,y=b,D=m,A=v):(_=l,R=c,O=u,L=f,X=b,y=g,D=v,A=m)),W===0)return null;let B=_/W,H=R/W,$=1/W,ne=O-B*G,oe=L-H*G,se=X-B*U,_e=y-H*U,me=D-B*z,Ee=A-H*z,Se=me*_e-Ee*se,Ze=ne*Ee-oe*me,rt=se*oe-_e*ne;if(s){if(Se<0||Ze<0||rt<0)return null}else if((Se<0||Ze<0||rt<0)&&(Se>0||Ze>0||rt>0))return null;let Ye=Se+Ze+rt;if(Ye===0)return null;let Ie=$*(Se*G+Ze*U+rt*z);return(Ye>0?Ie<0:Ie>0)?null:this.at(Ie/Ye,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},Mc=class extends Is{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new _t(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new js,this.combine=Lf,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}},ag=new nn,wr=new tr,ql=new er,lg=new ee,Yl=new ee,$l=new ee,Zl=new ee,_f=new ee,Jl=new ee,cg=new ee,Kl=new ee,ls=class extends ni{constructor(e=new ii,t=new Mc){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}getVertexPosition(e,t){let i=this.geometry,s=i.attributes.position,r=i.morphAttributes.position,o=i.morphTargetsRelative;t.fromBufferAttribute(s,e);let a=this.morphTargetInfluences;if(r&&a){Jl.set(0,0,0);for(let c=0,l=r.length;c<l;c++){let h=a[c],f=r[c];h!==0&&(_f.fromBufferAttribute(f,e),o?Jl.addScaledVector(_f,h):Jl.addScaledVector(_f.sub(t),h))}t.add(Jl)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),ql.copy(i.boundingSphere),ql.applyMatrix4(r),wr.copy(e.ray).recast(e.near),!(ql.containsPoint(wr.origin)===!1&&(wr.intersectSphere(ql,lg)===null||wr.origin.distanceToSquared(lg)>(e.far-e.near)**2))&&(ag.copy(r).invert(),wr.copy(e.ray).applyMatrix4(ag),!(i.boundingBox!==null&&wr.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(e,t,wr)))}_computeIntersections(e,t,i){let s,r=this.geometry,o=this.material,a=r.index,c=r.attributes.position,l=r.attributes.uv,h=r.attributes.uv1,f=r.attributes.normal,u=r.groups,p=r.drawRange;if(a!==null)if(Array.isArray(o))for(let g=0,b=u.length;g<b;g++){let d=u[g],m=o[d.materialIndex],v=Math.max(d.start,p.start),C=Math.min(a.count,Math.min(d.start+d.count,p.start+p.count));for(let S=v,P=C;S<P;S+=3){let T=a.getX(S),_=a.getX(S+1),R=a.getX(S+2);s=jl(this,m,e,i,l,h,f,T,_,R),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=d.materialIndex,t.push(s))}}else{let g=Math.max(0,p.start),b=Math.min(a.count,p.start+p.count);for(let d=g,m=b;d<m;d+=3){let v=a.getX(d),C=a.getX(d+1),S=a.getX(d+2);s=jl(this,o,e,i,l,h,f,v,C,S),s&&(s.faceIndex=Math.floor(d/3),t.push(s))}}else if(c!==void 0)if(Array.isArray(o))for(let g=0,b=u.length;g<b;g++){let d=u[g],m=o[d.materialIndex],v=Math.max(d.start,p.start),C=Math.min(c.count,Math.min(d.start+d.count,p.start+p.count));for(let S=v,P=C;S<P;S+=3){let T=S,_=S+1,R=S+2;s=jl(this,m,e,i,l,h,f,T,_,R),s&&(s.faceIndex=Math.floor(S/3),s.face.materialIndex=d.materialIndex,t.push(s))}}else{let g=Math.max(0,p.start),b=Math.min(c.count,p.start+p.count);for(let d=g,m=b;d<m;d+=3){let v=d,C=d+1,S=d+2;s=jl(this,o,e,i,l,h,f,v,C,S),s&&(s.faceIndex=Math.floor(d/3),t.push(s))}}}};function _v(n,e,t,i,s,r,o,a){let c;if(e.side===ei?c=i.intersectTriangle(o,r,s,!0,a):c=i.intersectTriangle(s,r,o,e.side===ar,a),c===null)return null;Kl.copy(a),Kl.applyMatrix4(n.matrixWorld);let l=t.ray.origin.distanceTo(Kl);return l<t.near||l>t.far?null:{distance:l,point:Kl.clone(),object:n}}function jl(n,e,t,i,s,r,o,a,c,l){n.getVertexPosition(a,Yl),n.getVertexPosition(c,$l),n.getVertexPosition(l,Zl);let h=_v(n,e,t,i,Yl,$l,Zl,cg);if(h){let f=new ee;Ks.getBarycoord(cg,Yl,$l,Zl,f),s&&(h.uv=Ks.getInterpolatedAttribute(s,a,c,l,f,new ft)),r&&(h.uv1=Ks.getInterpolatedAttribute(r,a,c,l,f,new ft)),o&&(h.normal=Ks.getInterpolatedAttribute(o,a,c,l,f,new ee),h.normal.dot(i.direction)>0&&h.normal.multiplyScalar(-1));let u={a,b:c,c:l,normal:new ee,materialIndex:0};Ks.getNormal(Yl,$l,Zl,u.normal),h.face=u,h.barycoord=f}return h}var bc=class extends ti{constructor(e=null,t=1,i=1,s,r,o,a,c,l=Bn,h=Bn,f,u){super(null,o,a,c,l,h,s,r,f,u),this.isDataTexture=!0,this.image={data:e,width:t,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var Er=new er,xv=new ft(.5,.5),Ql=new ee,Ar=class{constructor(e=new xi,t=new xi,i=new xi,s=new xi,r=new xi,o=new xi){this.planes=[e,t,i,s,r,o]}set(e,t,i,s,r,o){let a=this.planes;return a[0].copy(e),a[1].copy(t),a[2].copy(i),a[3].copy(s),a[4].copy(r),a[5].copy(o),this}copy(e){let t=this.planes;for(let i=0;i<6;i++)t[i].copy(e.planes[i]);return this}setFromProjectionMatrix(e,t=Li,i=!1){let s=this.planes,r=e.elements,o=r[0],a=r[1],c=r[2],l=r[3],h=r[4],f=r[5],u=r[6],p=r[7],g=r[8],b=r[9],d=r[10],m=r[11],v=r[12],C=r[13],S=r[14],P=r[15];if(s[0].setComponents(l-o,p-h,m-g,P-v).normalize(),s[1].setComponents(l+o,p+h,m+g,P+v).normalize(),s[2].setComponents(l+a,p+f,m+b,P+C).normalize(),s[3].setComponents(l-a,p-f,m-b,P-C).normalize(),i)s[4].setComponents(c,u,d,S).normalize(),s[5].setComponents(l-c,p-u,m-d,P-S).normalize();else if(s[4].setComponents(l-c,p-u,m-d,P-S).normalize(),t===Li)s[5].setComponents(l+c,p+u,m+d,P+S).normalize();else if(t===Sa)s[5].setComponents(c,u,d,S).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Er.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Er.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Er)}intersectsSprite(e){Er.center.set(0,0,0);let t=xv.distanceTo(e.center);return Er.radius=.7071067811865476+t,Er.applyMatrix4(e.matrixWorld),this.intersectsSphere(Er)}intersectsSphere(e){let t=this.planes,i=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(i)<s)return!1;return!0}intersectsBox(e){let t=this.planes;for(let i=0;i<6;i++){let s=t[i];if(Ql.x=s.normal.x>0?e.max.x:e.min.x,Ql.y=s.normal.y>0?e.max.y:e.min.y,Ql.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(Ql)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let i=0;i<6;i++)if(t[i].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},hg=new nn,wc=class n{constructor(){this.coordinateSystem=Li,this._frustums=[],this._count=0}setFromArrayCamera(e){let t=e.cameras,i=this._frustums;for(let s=0;s<t.length;s++){let r=t[s];hg.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),i[s]===void 0&&(i[s]=new Ar),i[s].setFromProjectionMatrix(hg,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsObject(e))return!0;return!1}intersectsSprite(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSprite(e))return!0;return!1}intersectsSphere(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSphere(e))return!0;return!1}intersectsBox(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsBox(e))return!0;return!1}containsPoint(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;let t=this._frustums,i=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Ar),t[s].copy(i[s]);return this._count=e._count,this}clone(){return new n().copy(this)}};var Ro=class extends Is{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new _t(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}},Ec=new ee,Tc=new ee,ug=new nn,pa=new tr,ec=new er,xf=new ee,fg=new ee,Ac=class extends ni{constructor(e=new ii,t=new Ro){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[0];for(let s=1,r=t.count;s<r;s++)Ec.fromBufferAttribute(t,s-1),Tc.fromBufferAttribute(t,s),i[s]=i[s-1],i[s]+=Ec.distanceTo(Tc);e.setAttribute("lineDistance",new On(i,1))}else et("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),ec.copy(i.boundingSphere),ec.applyMatrix4(s),ec.radius+=r,e.ray.intersectsSphere(ec)===!1)return;ug.copy(s).invert(),pa.copy(e.ray).applyMatrix4(ug);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),c=a*a,l=this.isLineSegments?2:1,h=i.index,u=i.attributes.position;if(h!==null){let p=Math.max(0,o.start),g=Math.min(h.count,o.start+o.count);for(let b=p,d=g-1;b<d;b+=l){let m=h.getX(b),v=h.getX(b+1),C=tc(this,e,pa,c,m,v,b);C&&t.push(C)}if(this.isLineLoop){let b=h.getX(g-1),d=h.getX(p),m=tc(this,e,pa,c,b,d,g-1);m&&t.push(m)}}else{let p=Math.max(0,o.start),g=Math.min(u.count,o.start+o.count);for(let b=p,d=g-1;b<d;b+=l){let m=tc(this,e,pa,c,b,b+1,b);m&&t.push(m)}if(this.isLineLoop){let b=tc(this,e,pa,c,g-1,p,g-1);b&&t.push(b)}}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function tc(n,e,t,i,s,r,o){let a=n.geometry.attributes.position;if(Ec.fromBufferAttribute(a,s),Tc.fromBufferAttribute(a,r),t.distanceSqToSegment(Ec,Tc,xf,fg)>i)return;xf.applyMatrix4(n.matrixWorld);let l=e.ray.origin.distanceTo(xf);if(!(l<e.near||l>e.far))return{distance:l,point:fg.clone().applyMatrix4(n.matrixWorld),index:o,face:null,faceIndex:null,barycoord:null,object:n}}var dg=new ee,pg=new ee,Ra=class extends Ac{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[];for(let s=0,r=t.count;s<r;s+=2)dg.fromBufferAttribute(t,s),pg.fromBufferAttribute(t,s+1),i[s]=s===0?0:i[s-1],i[s+1]=i[s]+dg.distanceTo(pg);e.setAttribute("lineDistance",new On(i,1))}else et("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}};var Co=class extends Is{constructor(e){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new _t(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.size=e.size,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}},mg=new nn,bf=new tr,nc=new er,ic=new ee,Ca=class extends ni{constructor(e=new ii,t=new Co){super(),this.isPoints=!0,this.type="Points",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Points.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),nc.copy(i.boundingSphere),nc.applyMatrix4(s),nc.radius+=r,e.ray.intersectsSphere(nc)===!1)return;mg.copy(s).invert(),bf.copy(e.ray).applyMatrix4(mg);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),c=a*a,l=i.index,f=i.attributes.position;if(l!==null){let u=Math.max(0,o.start),p=Math.min(l.count,o.start+o.count);for(let g=u,b=p;g<b;g++){let d=l.getX(g);ic.fromBufferAttribute(f,d),gg(ic,d,c,s,e,t,this)}}else{let u=Math.max(0,o.start),p=Math.min(f.count,o.start+o.count);for(let g=u,b=p;g<b;g++)ic.fromBufferAttribute(f,g),gg(ic,g,c,s,e,t,this)}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function gg(n,e,t,i,s,r,o){let a=bf.distanceSqToPoint(n);if(a<t){let c=new ee;bf.closestPointToPoint(n,c),c.applyMatrix4(i);let l=s.ray.origin.distanceTo(c);if(l<s.near||l>s.far)return;r.push({distance:l,distanceToRay:Math.sqrt(a),point:c,index:e,face:null,faceIndex:null,barycoord:null,object:o})}}var Pa=class extends ti{constructor(e=[],t=Pr,i,s,r,o,a,c,l,h){super(e,t,i,s,r,o,a,c,l,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}};var Ls=class extends ti{constructor(e,t,i=Wi,s,r,o,a=Bn,c=Bn,l,h=Ps,f=1){if(h!==Ps&&h!==Ns)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let u={width:e,height:t,depth:f};super(u,s,r,o,a,c,h,i,l),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new To(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}},Ia=class extends Ls{constructor(e,t=Wi,i=Pr,s,r,o=Bn,a=Bn,c,l=Ps){let h={width:e,height:e,depth:1},f=[h,h,h,h,h,h];super(e,e,t,i,s,r,o,a,c,l),this.image=f,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}},La=class extends ti{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}},Po=class n extends ii{constructor(e=1,t=1,i=1,s=1,r=1,o=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:i,widthSegments:s,heightSegments:r,depthSegments:o};let a=this;s=Math.floor(s),r=Math.floor(r),o=Math.floor(o);let c=[],l=[],h=[],f=[],u=0,p=0;g("z","y","x",-1,-1,i,t,e,o,r,0),g("z","y","x",1,-1,i,t,-e,o,r,1),g("x","z","y",1,1,e,i,t,s,o,2),g("x","z","y",1,-1,e,i,-t,s,o,3),g("x","y","z",1,-1,e,t,i,s,r,4),g("x","y","z",-1,-1,e,t,-i,s,r,5),this.setIndex(c),this.setAttribute("position",new On(l,3)),this.setAttribute("normal",new On(h,3)),this.setAttribute("uv",new On(f,2));function g(b,d,m,v,C,S,P,T,_,R,W){let O=S/_,L=P/R,G=S/2,X=P/2,y=T/2,U=_+1,D=R+1,A=0,z=0,B=new ee;for(let H=0;H<D;H++){let $=H*L-X;for(let ne=0;ne<U;ne++){let oe=ne*O-G;B[b]=oe*v,B[d]=$*C,B[m]=y,l.push(B.x,B.y,B.z),B[b]=0,B[d]=0,B[m]=T>0?1:-1,h.push(B.x,B.y,B.z),f.push(ne/_),f.push(1-H/R),A+=1}}for(let H=0;H<R;H++)for(let $=0;$<_;$++){let ne=u+$+U*H,oe=u+$+U*(H+1),se=u+($+1)+U*(H+1),_e=u+($+1)+U*H;c.push(ne,oe,_e),c.push(oe,se,_e),z+=6}a.addGroup(p,z,W),p+=z,u+=A}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};var Da=class n extends ii{constructor(e=1,t=1,i=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:i,heightSegments:s};let r=e/2,o=t/2,a=Math.floor(i),c=Math.floor(s),l=a+1,h=c+1,f=e/a,u=t/c,p=[],g=[],b=[],d=[];for(let m=0;m<h;m++){let v=m*u-o;for(let C=0;C<l;C++){let S=C*f-r;g.push(S,-v,0),b.push(0,0,1),d.push(C/a),d.push(1-m/c)}}for(let m=0;m<c;m++)for(let v=0;v<a;v++){let C=v+l*m,S=v+l*(m+1),P=v+1+l*(m+1),T=v+1+l*m;p.push(C,S,T),p.push(S,P,T)}this.setIndex(p),this.setAttribute("position",new On(g,3)),this.setAttribute("normal",new On(b,3)),this.setAttribute("uv",new On(d,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.widthSegments,e.heightSegments)}};function Lr(n){let e={};for(let t in n){e[t]={};for(let i in n[t]){let s=n[t][i];if(_g(s))s.isRenderTargetTexture?(et("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][i]=null):e[t][i]=s.clone();else if(Array.isArray(s))if(_g(s[0])){let r=[];for(let o=0,a=s.length;o<a;o++)r[o]=s[o].clone();e[t][i]=r}else e[t][i]=s.slice();else e[t][i]=s}}return e}function Wn(n){let e={};for(let t=0;t<n.length;t++){let i=Lr(n[t]);for(let s in i)e[s]=i[s]}return e}function _g(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function yv(n){let e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function sd(n){let e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:At.workingColorSpace}var l0={clone:Lr,merge:Wn},vv=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,Sv=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,cs=class extends Is{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=vv,this.fragmentShader=Sv,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Lr(e.uniforms),this.uniformsGroups=yv(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let s in this.uniforms){let o=this.uniforms[s].value;o&&o.isTexture?t.uniforms[s]={type:"t",value:o.toJSON(e).uuid}:o&&o.isColor?t.uniforms[s]={type:"c",value:o.getHex()}:o&&o.isVector2?t.uniforms[s]={type:"v2",value:o.toArray()}:o&&o.isVector3?t.uniforms[s]={type:"v3",value:o.toArray()}:o&&o.isVector4?t.uniforms[s]={type:"v4",value:o.toArray()}:o&&o.isMatrix3?t.uniforms[s]={type:"m3",value:o.toArray()}:o&&o.isMatrix4?t.uniforms[s]={type:"m4",value:o.toArray()}:t.uniforms[s]={value:o}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let i={};for(let s in this.extensions)this.extensions[s]===!0&&(i[s]=!0);return Object.keys(i).length>0&&(t.extensions=i),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(let i in e.uniforms){let s=e.uniforms[i];switch(this.uniforms[i]={},s.type){case"t":this.uniforms[i].value=t[s.value]||null;break;case"c":this.uniforms[i].value=new _t().setHex(s.value);break;case"v2":this.uniforms[i].value=new ft().fromArray(s.value);break;case"v3":this.uniforms[i].value=new ee().fromArray(s.value);break;case"v4":this.uniforms[i].value=new rn().fromArray(s.value);break;case"m3":this.uniforms[i].value=new lt().fromArray(s.value);break;case"m4":this.uniforms[i].value=new nn().fromArray(s.value);break;default:this.uniforms[i].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(let i in e.extensions)this.extensions[i]=e.extensions[i];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}},Rc=class extends cs{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}};var Cc=class extends Is{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=qg,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},Pc=class extends Is{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}};function yo(n,e){return!n||n.constructor===e?n:typeof e.BYTES_PER_ELEMENT=="number"?new e(n):Array.prototype.slice.call(n)}function sc(n){return n!==void 0&&n.inTangents!==void 0&&n.outTangents!==void 0}var nr=class{constructor(e,t,i,s){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=s!==void 0?s:new t.constructor(i),this.sampleValues=t,this.valueSize=i,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,i=this._cachedIndex,s=t[i],r=t[i-1];n:{e:{let o;t:{i:if(!(e<s)){for(let a=i+2;;){if(s===void 0){if(e<r)break i;return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}if(i===a)break;if(r=s,s=t[++i],e<s)break e}o=t.length;break t}if(!(e>=r)){let a=t[1];e<a&&(i=2,r=a);for(let c=i-2;;){if(r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(i===c)break;if(s=r,r=t[--i-1],e>=r)break e}o=i,i=0;break t}break n}for(;i<o;){let a=i+o>>>1;e<t[a]?o=a:i=a+1}if(s=t[i],r=t[i-1],r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(s===void 0)return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}this._cachedIndex=i,this.intervalChanged_(i,r,s)}return this.interpolate_(i,r,e,s)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,i=this.sampleValues,s=this.valueSize,r=e*s;for(let o=0;o!==s;++o)t[o]=i[r+o];return t}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},Ic=class extends nr{constructor(e,t,i,s){super(e,t,i,s),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:vf,endingEnd:vf}}intervalChanged_(e,t,i){let s=this.parameterPositions,r=e-2,o=e+1,a=s[r],c=s[o];if(a===void 0)switch(this.getSettings_().endingStart){case Sf:r=e,a=2*t-i;break;case Mf:r=s.length-2,a=t+s[r]-s[r+1];break;default:r=e,a=i}if(c===void 0)switch(this.getSettings_().endingEnd){case Sf:o=e,c=2*i-t;break;case Mf:o=1,c=i+s[1]-s[0];break;default:o=e-1,c=t}let l=(i-t)*.5,h=this.valueSize;this._weightPrev=l/(t-a),this._weightNext=l/(c-i),this._offsetPrev=r*h,this._offsetNext=o*h}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=e*a,l=c-a,h=this._offsetPrev,f=this._offsetNext,u=this._weightPrev,p=this._weightNext,g=(i-t)/(s-t),b=g*g,d=b*g,m=-u*d+2*u*b-u*g,v=(1+u)*d+(-1.5-2*u)*b+(-.5+u)*g+1,C=(-1-p)*d+(1.5+p)*b+.5*g,S=p*d-p*b;for(let P=0;P!==a;++P)r[P]=m*o[h+P]+v*o[l+P]+C*o[c+P]+S*o[f+P];return r}},Lc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=e*a,l=c-a,h=(i-t)/(s-t),f=1-h;for(let u=0;u!==a;++u)r[u]=o[l+u]*f+o[c+u]*h;return r}},Dc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e){return this.copySampleValue_(e-1)}},Nc=class extends nr{interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=e*a,l=c-a,h=this.inTangents,f=this.outTangents;if(!h||!f){let g=(i-t)/(s-t),b=1-g;for(let d=0;d!==a;++d)r[d]=o[l+d]*b+o[c+d]*g;return r}let u=a*2,p=e-1;for(let g=0;g!==a;++g){let b=o[l+g],d=o[c+g],m=p*u+g*2,v=f[m],C=f[m+1],S=e*u+g*2,P=h[S],T=h[S+1],_=bv(i,t,v,P,s);r[g]=c0(_,b,C,T,d)}return r}};function c0(n,e,t,i,s){let r=1-n;return r*r*r*e+3*r*r*n*t+3*r*n*n*i+n*n*n*s}function Mv(n,e,t,i,s){let r=1-n;return 3*r*r*(t-e)+6*r*n*(i-t)+3*n*n*(s-i)}function bv(n,e,t,i,s){let r=(n-e)/(s-e);for(let o=0;o<8;o++){let a=c0(r,e,t,i,s)-n;if(Math.abs(a)<1e-10)break;let c=Mv(r,e,t,i,s);if(Math.abs(c)<1e-10)break;r=Math.max(0,Math.min(1,r-a/c))}return r}var Mi=class{constructor(e,t,i,s){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=yo(t,this.TimeBufferType),this.values=yo(i,this.ValueBufferType),this.setInterpolation(s||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,i;if(t.toJSON!==this.toJSON)i=t.toJSON(e);else{i={name:e.name,times:yo(e.times,Array),values:yo(e.values,Array)};let s=e.getInterpolation();s!==e.DefaultInterpolation&&(i.interpolation=s),sc(e.settings)&&(i.settings={inTangents:yo(e.settings.inTangents,Array),outTangents:yo(e.settings.outTangents,Array)})}return i.type=e.ValueTypeName,i}InterpolantFactoryMethodDiscrete(e){return new Dc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new Lc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new Ic(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodBezier(e){let t=new Nc(this.times,this.values,this.getValueSize(),e);return this.settings&&(t.inTangents=this.settings.inTangents,t.outTangents=this.settings.outTangents),t}setInterpolation(e){let t;switch(e){case xa:t=this.InterpolantFactoryMethodDiscrete;break;case xc:t=this.InterpolantFactoryMethodLinear;break;case ac:t=this.InterpolantFactoryMethodSmooth;break;case yf:t=this.InterpolantFactoryMethodBezier;break}if(t===void 0){let i="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(i);return et("KeyframeTrack:",i),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return xa;case this.InterpolantFactoryMethodLinear:return xc;case this.InterpolantFactoryMethodSmooth:return ac;case this.InterpolantFactoryMethodBezier:return yf}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]+=e;sc(this.settings)&&(xg(this.settings.inTangents,e),xg(this.settings.outTangents,e))}return this}scale(e){if(e!==1){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]*=e;sc(this.settings)&&(yg(this.settings.inTangents,e),yg(this.settings.outTangents,e))}return this}trim(e,t){let i=this.times,s=i.length,r=0,o=s-1;for(;r!==s&&i[r]<e;)++r;for(;o!==-1&&i[o]>t;)--o;if(++o,r!==0||o!==s){r>=o&&(o=Math.max(o,1),r=o-1);let a=this.getValueSize();this.times=i.slice(r,o),this.values=this.values.slice(r*a,o*a)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(at("KeyframeTrack: Invalid value size in track.",this),e=!1);let i=this.times,s=this.values,r=i.length;r===0&&(at("KeyframeTrack: Track is empty.",this),e=!1);let o=null;for(let a=0;a!==r;a++){let c=i[a];if(typeof c=="number"&&isNaN(c)){at("KeyframeTrack: Time is not a valid number.",this,a,c),e=!1;break}if(o!==null&&o>c){at("KeyframeTrack: Out of order keys.",this,a,c,o),e=!1;break}o=c}if(s!==void 0&&ky(s))for(let a=0,c=s.length;a!==c;++a){let l=s[a];if(isNaN(l)){at("KeyframeTrack: Value is not a valid number.",this,a,l),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),i=this.getValueSize(),s=this.getInterpolation()===ac,r=e.length-1,o=1;for(let a=1;a<r;++a){let c=!1,l=e[a],h=e[a+1];if(l!==h&&(a!==1||l!==e[0]))if(s)c=!0;else{let f=a*i,u=f-i,p=f+i;for(let g=0;g!==i;++g){let b=t[f+g];if(b!==t[u+g]||b!==t[p+g]){c=!0;break}}}if(c){if(a!==o){e[o]=e[a];let f=a*i,u=o*i;for(let p=0;p!==i;++p)t[u+p]=t[f+p]}++o}}if(r>0){e[o]=e[r];for(let a=r*i,c=o*i,l=0;l!==i;++l)t[c+l]=t[a+l];++o}return o!==e.length?(this.times=e.slice(0,o),this.values=t.slice(0,o*i)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),i=this.constructor,s=new i(this.name,e,t);return s.createInterpolant=this.createInterpolant,sc(this.settings)&&(s.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),s}};function xg(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]+=e}function yg(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]*=e}Mi.prototype.ValueTypeName="";Mi.prototype.TimeBufferType=Float32Array;Mi.prototype.ValueBufferType=Float32Array;Mi.prototype.DefaultInterpolation=xc;var ir=class extends Mi{constructor(e,t,i){super(e,t,i)}};ir.prototype.ValueTypeName="bool";ir.prototype.ValueBufferType=Array;ir.prototype.DefaultInterpolation=xa;ir.prototype.InterpolantFactoryMethodLinear=void 0;ir.prototype.InterpolantFactoryMethodSmooth=void 0;var Uc=class extends Mi{constructor(e,t,i,s){super(e,t,i,s)}};Uc.prototype.ValueTypeName="color";var Fc=class extends Mi{constructor(e,t,i,s){super(e,t,i,s)}};Fc.prototype.ValueTypeName="number";var Oc=class extends nr{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=(i-t)/(s-t),l=e*a;for(let h=l+a;l!==h;l+=4)vi.slerpFlat(r,0,o,l-a,o,l,c);return r}},Na=class extends Mi{constructor(e,t,i,s){super(e,t,i,s)}InterpolantFactoryMethodLinear(e){return new Oc(this.times,this.values,this.getValueSize(),e)}};Na.prototype.ValueTypeName="quaternion";Na.prototype.InterpolantFactoryMethodSmooth=void 0;var sr=class extends Mi{constructor(e,t,i){super(e,t,i)}};sr.prototype.ValueTypeName="string";sr.prototype.ValueBufferType=Array;sr.prototype.DefaultInterpolation=xa;sr.prototype.InterpolantFactoryMethodLinear=void 0;sr.prototype.InterpolantFactoryMethodSmooth=void 0;var Bc=class extends Mi{constructor(e,t,i,s){super(e,t,i,s)}};Bc.prototype.ValueTypeName="vector";var kc=class{constructor(e,t,i){let s=this,r=!1,o=0,a=0,c,l=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=i,this._abortController=null,this.itemStart=function(h){a++,r===!1&&s.onStart!==void 0&&s.onStart(h,o,a),r=!0},this.itemEnd=function(h){o++,s.onProgress!==void 0&&s.onProgress(h,o,a),o===a&&(r=!1,s.onLoad!==void 0&&s.onLoad())},this.itemError=function(h){s.onError!==void 0&&s.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),c?c(h):h},this.setURLModifier=function(h){return c=h,this},this.addHandler=function(h,f){return l.push(h,f),this},this.removeHandler=function(h){let f=l.indexOf(h);return f!==-1&&l.splice(f,2),this},this.getHandler=function(h){for(let f=0,u=l.length;f<u;f+=2){let p=l[f],g=l[f+1];if(p.global&&(p.lastIndex=0),p.test(h))return g}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},h0=new kc,zc=class{constructor(e){this.manager=e!==void 0?e:h0,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(e,t){let i=this;return new Promise(function(s,r){i.load(e,s,t,r)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}setPriority(e){return this.priority=e,this}setCache(e){return this.cache=e,this}abort(){return this}};zc.DEFAULT_MATERIAL_NAME="__DEFAULT";var rc=new ee,oc=new vi,os=new ee,Ua=class extends ni{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new nn,this.projectionMatrix=new nn,this.projectionMatrixInverse=new nn,this.coordinateSystem=Li,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(rc,oc,os),os.x===1&&os.y===1&&os.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(rc,oc,os.set(1,1,1)).invert()}updateWorldMatrix(e,t,i=!1){super.updateWorldMatrix(e,t,i),this.matrixWorld.decompose(rc,oc,os),os.x===1&&os.y===1&&os.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(rc,oc,os.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},Js=new ee,vg=new ft,Sg=new ft,jn=class extends Ua{constructor(e=50,t=1,i=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=i,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=Eo*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(ga*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Eo*2*Math.atan(Math.tan(ga*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,i){Js.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(Js.x,Js.y).multiplyScalar(-e/Js.z),Js.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set(Js.x,Js.y).multiplyScalar(-e/Js.z)}getViewSize(e,t){return this.getViewBounds(e,vg,Sg),t.subVectors(Sg,vg)}setViewOffset(e,t,i,s,r,o){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(ga*.5*this.fov)/this.zoom,i=2*t,s=this.aspect*i,r=-.5*s,o=this.view;if(this.view!==null&&this.view.enabled){let c=o.fullWidth,l=o.fullHeight;r+=o.offsetX*s/c,t-=o.offsetY*i/l,s*=o.width/c,i*=o.height/l}let a=this.filmOffset;a!==0&&(r+=e*a/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-i,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}};var Vc=class extends Ua{constructor(e=-1,t=1,i=1,s=-1,r=.1,o=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=i,this.bottom=s,this.near=r,this.far=o,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,i,s,r,o){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,s=(this.top+this.bottom)/2,r=i-e,o=i+e,a=s+t,c=s-t;if(this.view!==null&&this.view.enabled){let l=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=l*this.view.offsetX,o=r+l*this.view.width,a-=h*this.view.offsetY,c=a-h*this.view.height}this.projectionMatrix.makeOrthographic(r,o,a,c,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}};var vo=-90,So=1,Io=class extends ni{constructor(e,t,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;let s=new jn(vo,So,e,t);s.layers=this.layers,this.add(s);let r=new jn(vo,So,e,t);r.layers=this.layers,this.add(r);let o=new jn(vo,So,e,t);o.layers=this.layers,this.add(o);let a=new jn(vo,So,e,t);a.layers=this.layers,this.add(a);let c=new jn(vo,So,e,t);c.layers=this.layers,this.add(c);let l=new jn(vo,So,e,t);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[i,s,r,o,a,c]=t;for(let l of t)this.remove(l);if(e===Li)i.up.set(0,1,0),i.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),o.up.set(0,0,1),o.lookAt(0,-1,0),a.up.set(0,1,0),a.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(e===Sa)i.up.set(0,-1,0),i.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),o.up.set(0,0,-1),o.lookAt(0,-1,0),a.up.set(0,-1,0),a.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let l of t)this.add(l),l.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:i,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[r,o,a,c,l,h]=this.children,f=e.getRenderTarget(),u=e.getActiveCubeFace(),p=e.getActiveMipmapLevel(),g=e.xr.enabled;e.xr.enabled=!1;let b=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let d=!1;e.isWebGLRenderer===!0?d=e.state.buffers.depth.getReversed():d=e.reversedDepthBuffer,e.setRenderTarget(i,0,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(i,1,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(i,2,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(i,3,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),e.setRenderTarget(i,4,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),i.texture.mipmapsAutoUpdate=b,e.setRenderTarget(i,5,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(f,u,p),e.xr.enabled=g,i.texture.needsPMREMUpdate=!0}},Hc=class extends jn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}};var rd="\\[\\]\\.:\\/",wv=new RegExp("["+rd+"]","g"),od="[^"+rd+"]",Ev="[^"+rd.replace("\\.","")+"]",Tv=/((?:WC+[\/:])*)/.source.replace("WC",od),Av=/(WCOD+)?/.source.replace("WCOD",Ev),Rv=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",od),Cv=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",od),Pv=new RegExp("^"+Tv+Av+Rv+Cv+"$"),Iv=["material","materials","bones","map"],wf=class{constructor(e,t,i){let s=i||en.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,s)}getValue(e,t){this.bind();let i=this._targetGroup.nCachedObjects_,s=this._bindings[i];s!==void 0&&s.getValue(e,t)}setValue(e,t){let i=this._bindings;for(let s=this._targetGroup.nCachedObjects_,r=i.length;s!==r;++s)i[s].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].unbind()}},en=class n{constructor(e,t,i){this.path=t,this.parsedPath=i||n.parseTrackName(t),this.node=n.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,i){return e&&e.isAnimationObjectGroup?new n.Composite(e,t,i):new n(e,t,i)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(wv,"")}static parseTrackName(e){let t=Pv.exec(e);if(t===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+e);let i={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},s=i.nodeName&&i.nodeName.lastIndexOf(".");if(s!==void 0&&s!==-1){let r=i.nodeName.substring(s+1);Iv.indexOf(r)!==-1&&(i.nodeName=i.nodeName.substring(0,s),i.objectName=r)}if(i.propertyName===null||i.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+e);return i}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let i=e.skeleton.getBoneByName(t);if(i!==void 0)return i}if(e.children){let i=function(r){for(let o=0;o<r.length;o++){let a=r[o];if(a.name===t||a.uuid===t)return a;let c=i(a.children);if(c)return c}return null},s=i(e.children);if(s)return s}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)e[t++]=i[s]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,i=t.objectName,s=t.propertyName,r=t.propertyIndex;if(e||(e=n.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){et("PropertyBinding: No target node found for track: "+this.path+".");return}if(i){let l=t.objectIndex;switch(i){case"materials":if(!e.material){at("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){at("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){at("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let h=0;h<e.length;h++)if(e[h].name===l){l=h;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){at("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){at("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[i]===void 0){at("PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[i]}if(l!==void 0){if(e[l]===void 0){at("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[l]}}let o=e[s];if(o===void 0){let l=t.nodeName;at("PropertyBinding: Trying to update property for track: "+l+"."+s+" but it wasn't found.",e);return}let a=this.Versioning.None;this.targetObject=e,e.isMaterial===!0?a=this.Versioning.NeedsUpdate:e.isObject3D===!0&&(a=this.Versioning.MatrixWorldNeedsUpdate);let c=this.BindingType.Direct;if(r!==void 0){if(s==="morphTargetInfluences"){if(!e.geometry){at("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){at("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[r]!==void 0&&(r=e.morphTargetDictionary[r])}c=this.BindingType.ArrayElement,this.resolvedProperty=o,this.propertyIndex=r}else o.fromArray!==void 0&&o.toArray!==void 0?(c=this.BindingType.HasFromToArray,this.resolvedProperty=o):Array.isArray(o)?(c=this.BindingType.EntireArray,this.resolvedProperty=o):this.propertyName=s;this.getValue=this.GetterByBindingType[c],this.setValue=this.SetterByBindingTypeAndVersioning[c][a]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};en.Composite=wf;en.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};en.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};en.prototype.GetterByBindingType=[en.prototype._getValue_direct,en.prototype._getValue_array,en.prototype._getValue_arrayElement,en.prototype._getValue_toArray];en.prototype.SetterByBindingTypeAndVersioning=[[en.prototype._setValue_direct,en.prototype._setValue_direct_setNeedsUpdate,en.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[en.prototype._setValue_array,en.prototype._setValue_array_setNeedsUpdate,en.prototype._setValue_array_setMatrixWorldNeedsUpdate],[en.prototype._setValue_arrayElement,en.prototype._setValue_arrayElement_setNeedsUpdate,en.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[en.prototype._setValue_fromArray,en.prototype._setValue_fromArray_setNeedsUpdate,en.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var CT=new Float32Array(1);var Lo=class{constructor(e=1,t=0,i=0){this.radius=e,this.phi=t,this.theta=i}set(e,t,i){return this.radius=e,this.phi=t,this.theta=i,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=Mt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,i){return this.radius=Math.sqrt(e*e+t*t+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,i),this.phi=Math.acos(Mt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var fd=class fd{constructor(e,t,i,s){this.elements=[1,0,0,1],e!==void 0&&this.set(e,t,i,s)}identity(){return this.set(1,0,0,1),this}fromArray(e,t=0){for(let i=0;i<4;i++)this.elements[i]=e[i+t];return this}set(e,t,i,s){let r=this.elements;return r[0]=e,r[2]=t,r[1]=i,r[3]=s,this}};fd.prototype.isMatrix2=!0;var Ef=fd;var Fa=class extends Ra{constructor(e=10,t=10,i=4473924,s=8947848){i=new _t(i),s=new _t(s);let r=t/2,o=e/t,a=e/2,c=[],l=[];for(let u=0,p=0,g=-a;u<=t;u++,g+=o){c.push(-a,0,g,a,0,g),c.push(g,0,-a,g,0,a);let b=u===r?i:s;b.toArray(l,p),p+=3,b.toArray(l,p),p+=3,b.toArray(l,p),p+=3,b.toArray(l,p),p+=3}let h=new ii;h.setAttribute("position",new On(c,3)),h.setAttribute("color",new On(l,3));let f=new Ro({vertexColors:!0,toneMapped:!1});super(h,f),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Oa=class extends Ra{constructor(e=1){let t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],i=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new ii;s.setAttribute("position",new On(t,3)),s.setAttribute("color",new On(i,3));let r=new Ro({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,i){let s=new _t,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(i),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Ba=class extends Gi{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function ad(n,e,t,i){let s=Lv(i);switch(t){case Xf:return n*e;case Yf:return n*e/s.components*s.byteLength;case Jc:return n*e/s.components*s.byteLength;case lr:return n*e*2/s.components*s.byteLength;case Kc:return n*e*2/s.components*s.byteLength;case qf:return n*e*3/s.components*s.byteLength;case Yi:return n*e*4/s.components*s.byteLength;case jc:return n*e*4/s.components*s.byteLength;case Va:case Ha:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case Ga:case Wa:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case eh:case nh:return Math.max(n,16)*Math.max(e,8)/4;case Qc:case th:return Math.max(n,8)*Math.max(e,8)/2;case ih:case sh:case oh:case ah:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case rh:case Xa:case lh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case ch:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case hh:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case uh:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case fh:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case dh:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case ph:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case mh:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case gh:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case _h:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case xh:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case yh:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case vh:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case Sh:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case Mh:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case bh:case wh:case Eh:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Th:case Ah:return Math.ceil(n/4)*Math.ceil(e/4)*8;case qa:case Rh:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function Lv(n){switch(n){case bi:case Vf:return{byteLength:1,components:1};case Fo:case Hf:case qi:return{byteLength:2,components:1};case $c:case Zc:return{byteLength:2,components:4};case Wi:case Yc:case Xi:return{byteLength:4,components:1};case Gf:case Wf:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?et("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187");function L0(){let n=null,e=!1,t=null,i=null;function s(r,o){i=n.requestAnimationFrame(s),t(r,o)}return{start:function(){e!==!0&&t!==null&&n!==null&&(i=n.requestAnimationFrame(s),e=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){n=r}}}function Nv(n){let e=new WeakMap;function t(a,c){let l=a.array,h=a.usage,f=l.byteLength,u=n.createBuffer();n.bindBuffer(c,u),n.bufferData(c,l,h),a.onUploadCallback();let p;if(l instanceof Float32Array)p=n.FLOAT;else if(typeof Float16Array<"u"&&l instanceof Float16Array)p=n.HALF_FLOAT;else if(l instanceof Uint16Array)a.isFloat16BufferAttribute?p=n.HALF_FLOAT:p=n.UNSIGNED_SHORT;else if(l instanceof Int16Array)p=n.SHORT;else if(l instanceof Uint32Array)p=n.UNSIGNED_INT;else if(l instanceof Int32Array)p=n.INT;else if(l instanceof Int8Array)p=n.BYTE;else if(l instanceof Uint8Array)p=n.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)p=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:u,type:p,bytesPerElement:l.BYTES_PER_ELEMENT,version:a.version,size:f}}function i(a,c,l){let h=c.array,f=c.updateRanges;if(n.bindBuffer(l,a),f.length===0)n.bufferSubData(l,0,h);else{f.sort((p,g)=>p.start-g.start);let u=0;for(let p=1;p<f.length;p++){let g=f[u],b=f[p];b.start<=g.start+g.count+1?g.count=Math.max(g.count,b.start+b.count-g.start):(++u,f[u]=b)}f.length=u+1;for(let p=0,g=f.length;p<g;p++){let b=f[p];n.bufferSubData(l,b.start*h.BYTES_PER_ELEMENT,h,b.start,b.count)}c.clearUpdateRanges()}c.onUploadCallback()}function s(a){return a.isInterleavedBufferAttribute&&(a=a.data),e.get(a)}function r(a){a.isInterleavedBufferAttribute&&(a=a.data);let c=e.get(a);c&&(n.deleteBuffer(c.buffer),e.delete(a))}function o(a,c){if(a.isInterleavedBufferAttribute&&(a=a.data),a.isGLBufferAttribute){let h=e.get(a);(!h||h.version<a.version)&&e.set(a,{buffer:a.buffer,type:a.type,bytesPerElement:a.elementSize,version:a.version});return}let l=e.get(a);if(l===void 0)e.set(a,t(a,c));else if(l.version<a.version){if(l.size!==a.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(l.buffer,a,c),l.version=a.version}}return{get:s,remove:r,update:o}}var Uv=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,Fv=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,Ov=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,Bv=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,kv=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,zv=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,Vv=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,Hv=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,Gv=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,Wv=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Xv=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,qv=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,Yv=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,$v=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,Zv=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,Jv=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,Kv=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,jv=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,Qv=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,eS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,tS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,nS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,iS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,sS=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,rS=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,oS=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,aS=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,lS=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,cS=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,hS="gl_FragColor = linearToOutputTexel( gl_FragColor );",uS=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,fS=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,dS=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,pS=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,mS=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,gS=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,_S=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,xS=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,yS=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,vS=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,SS=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,MS=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,bS=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,wS=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,ES=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,TS=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,AS=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,RS=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,CS=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,PS=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,IS=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,LS=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,DS=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,NS=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,US=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,FS=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,OS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,BS=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,kS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,zS=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,VS=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,HS=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,GS=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,WS=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,XS=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,qS=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,YS=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,$S=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,ZS=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,JS=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,KS=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,jS=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,QS=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,eM=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,tM=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,nM=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,iM=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,sM=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,rM=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,oM=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,aM=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,lM=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,cM=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,hM=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,uM=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,fM=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,dM=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,pM=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,mM=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,gM=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,_M=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,xM=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,yM=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,vM=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,SM=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,MM=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,bM=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,wM=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,EM=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,TM=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,AM=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,RM=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,CM=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,PM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,IM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,LM=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,DM=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,NM=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,UM=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,FM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,OM=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,BM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,kM=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,zM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,VM=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,HM=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,GM=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,WM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,XM=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,qM=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,YM=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,$M=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,ZM=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,JM=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,KM=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,jM=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,QM=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,eb=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,tb=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,nb=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,ib=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,sb=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,rb=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ob=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,ab=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,lb=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,cb=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,hb=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,ub=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,fb=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,db=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,xt={alphahash_fragment:Uv,alphahash_pars_fragment:Fv,alphamap_fragment:Ov,alphamap_pars_fragment:Bv,alphatest_fragment:kv,alphatest_pars_fragment:zv,aomap_fragment:Vv,aomap_pars_fragment:Hv,batching_pars_vertex:Gv,batching_vertex:Wv,begin_vertex:Xv,beginnormal_vertex:qv,bsdfs:Yv,iridescence_fragment:$v,bumpmap_pars_fragment:Zv,clipping_planes_fragment:Jv,clipping_planes_pars_fragment:Kv,clipping_planes_pars_vertex:jv,clipping_planes_vertex:Qv,color_fragment:eS,color_pars_fragment:tS,color_pars_vertex:nS,color_vertex:iS,common:sS,defaultnormal_vertex:rS,displacementmap_pars_vertex:oS,displacementmap_vertex:aS,emissivemap_fragment:lS,emissivemap_pars_fragment:cS,colorspace_fragment:hS,colorspace_pars_fragment:uS,envmap_fragment:fS,envmap_common_pars_fragment:dS,envmap_pars_fragment:pS,envmap_pars_vertex:mS,envmap_physical_pars_fragment:TS,envmap_vertex:gS,fog_vertex:_S,fog_pars_vertex:xS,fog_fragment:yS,fog_pars_fragment:vS,gradientmap_pars_fragment:SS,lightmap_pars_fragment:MS,lights_lambert_fragment:bS,lights_lambert_pars_fragment:wS,lights_pars_begin:ES,lights_toon_fragment:AS,lights_toon_pars_fragment:RS,lights_phong_fragment:CS,lights_phong_pars_fragment:PS,lights_physical_fragment:IS,lights_physical_pars_fragment:LS,lights_fragment_begin:DS,lights_fragment_maps:NS,lights_fragment_end:US,lightprobes_pars_fragment:FS,logdepthbuf_fragment:OS,logdepthbuf_pars_fragment:BS,logdepthbuf_pars_vertex:kS,logdepthbuf_vertex:zS,map_fragment:VS,map_pars_fragment:HS,map_particle_fragment:GS,map_particle_pars_fragment:WS,metalnessmap_fragment:XS,metalnessmap_pars_fragment:qS,morphinstance_vertex:YS,morphcolor_vertex:$S,morphnormal_vertex:ZS,morphtarget_pars_vertex:JS,morphtarget_vertex:KS,normal_fragment_begin:jS,normal_fragment_maps:QS,normal_pars_fragment:eM,normal_pars_vertex:tM,normal_vertex:nM,normalmap_pars_fragment:iM,clearcoat_normal_fragment_begin:sM,clearcoat_normal_fragment_maps:rM,clearcoat_pars_fragment:oM,iridescence_pars_fragment:aM,opaque_fragment:lM,packing:cM,premultiplied_alpha_fragment:hM,project_vertex:uM,dithering_fragment:fM,dithering_pars_fragment:dM,roughnessmap_fragment:pM,roughnessmap_pars_fragment:mM,shadowmap_pars_fragment:gM,shadowmap_pars_vertex:_M,shadowmap_vertex:xM,shadowmask_pars_fragment:yM,skinbase_vertex:vM,skinning_pars_vertex:SM,skinning_vertex:MM,skinnormal_vertex:bM,specularmap_fragment:wM,specularmap_pars_fragment:EM,tonemapping_fragment:TM,tonemapping_pars_fragment:AM,transmission_fragment:RM,transmission_pars_fragment:CM,uv_pars_fragment:PM,uv_pars_vertex:IM,uv_vertex:LM,worldpos_vertex:DM,background_vert:NM,background_frag:UM,backgroundCube_vert:FM,backgroundCube_frag:OM,cube_vert:BM,cube_frag:kM,depth_vert:zM,depth_frag:VM,distance_vert:HM,distance_frag:GM,equirect_vert:WM,equirect_frag:XM,linedashed_vert:qM,linedashed_frag:YM,meshbasic_vert:$M,meshbasic_frag:ZM,meshlambert_vert:JM,meshlambert_frag:KM,meshmatcap_vert:jM,meshmatcap_frag:QM,meshnormal_vert:eb,meshnormal_frag:tb,meshphong_vert:nb,meshphong_frag:ib,meshphysical_vert:sb,meshphysical_frag:rb,meshtoon_vert:ob,meshtoon_frag:ab,points_vert:lb,points_frag:cb,shadow_vert:hb,shadow_frag:ub,sprite_vert:fb,sprite_frag:db},Oe={common:{diffuse:{value:new _t(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new lt},alphaMap:{value:null},alphaMapTransform:{value:new lt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new lt}},envmap:{envMap:{value:null},envMapRotation:{value:new lt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new lt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new lt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new lt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new lt},normalScale:{value:new ft(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new lt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new lt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new lt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new lt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new _t(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new _t(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new lt},alphaTest:{value:0},uvTransform:{value:new lt}},sprite:{diffuse:{value:new _t(16777215)},opacity:{value:1},center:{value:new ft(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new lt},alphaMap:{value:null},alphaMapTransform:{value:new lt},alphaTest:{value:0}}},ds={basic:{uniforms:Wn([Oe.common,Oe.specularmap,Oe.envmap,Oe.aomap,Oe.lightmap,Oe.fog]),vertexShader:xt.meshbasic_vert,fragmentShader:xt.meshbasic_frag},lambert:{uniforms:Wn([Oe.common,Oe.specularmap,Oe.envmap,Oe.aomap,Oe.lightmap,Oe.emissivemap,Oe.bumpmap,Oe.normalmap,Oe.displacementmap,Oe.fog,Oe.lights,{emissive:{value:new _t(0)},envMapIntensity:{value:1}}]),vertexShader:xt.meshlambert_vert,fragmentShader:xt.meshlambert_frag},phong:{uniforms:Wn([Oe.common,Oe.specularmap,Oe.envmap,Oe.aomap,Oe.lightmap,Oe.emissivemap,Oe.bumpmap,Oe.normalmap,Oe.displacementmap,Oe.fog,Oe.lights,{emissive:{value:new _t(0)},specular:{value:new _t(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:xt.meshphong_vert,fragmentShader:xt.meshphong_frag},standard:{uniforms:Wn([Oe.common,Oe.envmap,Oe.aomap,Oe.lightmap,Oe.emissivemap,Oe.bumpmap,Oe.normalmap,Oe.displacementmap,Oe.roughnessmap,Oe.metalnessmap,Oe.fog,Oe.lights,{emissive:{value:new _t(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:xt.meshphysical_vert,fragmentShader:xt.meshphysical_frag},toon:{uniforms:Wn([Oe.common,Oe.aomap,Oe.lightmap,Oe.emissivemap,Oe.bumpmap,Oe.normalmap,Oe.displacementmap,Oe.gradientmap,Oe.fog,Oe.lights,{emissive:{value:new _t(0)}}]),vertexShader:xt.meshtoon_vert,fragmentShader:xt.meshtoon_frag},matcap:{uniforms:Wn([Oe.common,Oe.bumpmap,Oe.normalmap,Oe.displacementmap,Oe.fog,{matcap:{value:null}}]),vertexShader:xt.meshmatcap_vert,fragmentShader:xt.meshmatcap_frag},points:{uniforms:Wn([Oe.points,Oe.fog]),vertexShader:xt.points_vert,fragmentShader:xt.points_frag},dashed:{uniforms:Wn([Oe.common,Oe.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:xt.linedashed_vert,fragmentShader:xt.linedashed_frag},depth:{uniforms:Wn([Oe.common,Oe.displacementmap]),vertexShader:xt.depth_vert,fragmentShader:xt.depth_frag},normal:{uniforms:Wn([Oe.common,Oe.bumpmap,Oe.normalmap,Oe.displacementmap,{opacity:{value:1}}]),vertexShader:xt.meshnormal_vert,fragmentShader:xt.meshnormal_frag},sprite:{uniforms:Wn([Oe.sprite,Oe.fog]),vertexShader:xt.sprite_vert,fragmentShader:xt.sprite_frag},background:{uniforms:{uvTransform:{value:new lt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:xt.background_vert,fragmentShader:xt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new lt}},vertexShader:xt.backgroundCube_vert,fragmentShader:xt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:xt.cube_vert,fragmentShader:xt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:xt.equirect_vert,fragmentShader:xt.equirect_frag},distance:{uniforms:Wn([Oe.common,Oe.displacementmap,{referencePosition:{value:new ee},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:xt.distance_vert,fragmentShader:xt.distance_frag},shadow:{uniforms:Wn([Oe.lights,Oe.fog,{color:{value:new _t(0)},opacity:{value:1}}]),vertexShader:xt.shadow_vert,fragmentShader:xt.shadow_frag}};ds.physical={uniforms:Wn([ds.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new lt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new lt},clearcoatNormalScale:{value:new ft(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new lt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new lt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new lt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new lt},sheen:{value:0},sheenColor:{value:new _t(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new lt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new lt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new lt},transmissionSamplerSize:{value:new ft},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new lt},attenuationDistance:{value:0},attenuationColor:{value:new _t(0)},specularColor:{value:new _t(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new lt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new lt},anisotropyVector:{value:new ft},anisotropyMap:{value:null},anisotropyMapTransform:{value:new lt}}]),vertexShader:xt.meshphysical_vert,fragmentShader:xt.meshphysical_frag};var Ch={r:0,b:0,g:0},pb=new nn,D0=new lt;D0.set(-1,0,0,0,1,0,0,0,1);function mb(n,e,t,i,s,r){let o=new _t(0),a=s===!0?0:1,c,l,h=null,f=0,u=null;function p(v){let C=v.isScene===!0?v.background:null;if(C&&C.isTexture){let S=v.backgroundBlurriness>0;C=e.get(C,S)}return C}function g(v){let C=!1,S=p(v);S===null?d(o,a):S&&S.isColor&&(d(S,1),C=!0);let P=n.xr.getEnvironmentBlendMode();P==="additive"?t.buffers.color.setClear(0,0,0,1,r):P==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(n.autoClear||C)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function b(v,C){let S=p(C);S&&S.isCubeTexture?(l===void 0&&(l=new ls(new Po(1,1,1),new cs({name:"BackgroundCubeMaterial",uniforms:Lr(ds.backgroundCube.uniforms),vertexShader:ds.backgroundCube.vertexShader,fragmentShader:ds.backgroundCube.fragmentShader,side:ei,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),l.geometry.deleteAttribute("uv"),l.onBeforeRender=function(P,T,_){this.matrixWorld.copyPosition(_.matrixWorld)},Object.defineProperty(l.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(l)),l.material.uniforms.envMap.value=S,l.material.uniforms.backgroundBlurriness.value=C.backgroundBlurriness,l.material.uniforms.backgroundIntensity.value=C.backgroundIntensity,l.material.uniforms.backgroundRotation.value.setFromMatrix4(pb.makeRotationFromEuler(C.backgroundRotation)).transpose(),S.isRenderTargetTexture===!1&&l.material.uniforms.backgroundRotation.value.premultiply(D0),l.material.toneMapped=At.getTransfer(S.colorSpace)!==kt,(h!==S||f!==S.version||u!==n.toneMapping)&&(l.material.needsUpdate=!0,h=S,f=S.version,u=n.toneMapping),l.layers.enableAll(),v.unshift(l,l.geometry,l.material,0,0,null)):S&&S.isTexture&&(c===void 0&&(c=new ls(new Da(2,2),new cs({name:"BackgroundMaterial",uniforms:Lr(ds.background.uniforms),vertexShader:ds.background.vertexShader,fragmentShader:ds.background.fragmentShader,side:ar,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),Object.defineProperty(c.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(c)),c.material.uniforms.t2D.value=S,c.material.uniforms.backgroundIntensity.value=C.backgroundIntensity,c.material.toneMapped=At.getTransfer(S.colorSpace)!==kt,S.matrixAutoUpdate===!0&&S.updateMatrix(),c.material.uniforms.uvTransform.value.copy(S.matrix),(h!==S||f!==S.version||u!==n.toneMapping)&&(c.material.needsUpdate=!0,h=S,f=S.version,u=n.toneMapping),c.layers.enableAll(),v.unshift(c,c.geometry,c.material,0,0,null))}function d(v,C){v.getRGB(Ch,sd(n)),t.buffers.color.setClear(Ch.r,Ch.g,Ch.b,C,r)}function m(){l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0),c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0)}return{getClearColor:function(){return o},setClearColor:function(v,C=1){o.set(v),a=C,d(o,a)},getClearAlpha:function(){return a},setClearAlpha:function(v){a=v,d(o,a)},render:g,addToRenderList:b,dispose:m}}function gb(n,e){let t=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},s=u(null),r=s,o=!1;function a(L,G,X,y,U){let D=!1,A=f(L,y,X,G);r!==A&&(r=A,l(r.object)),D=p(L,y,X,U),D&&g(L,y,X,U),U!==null&&e.update(U,n.ELEMENT_ARRAY_BUFFER),(D||o)&&(o=!1,S(L,G,X,y),U!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(U).buffer))}function c(){return n.createVertexArray()}function l(L){return n.bindVertexArray(L)}function h(L){return n.deleteVertexArray(L)}function f(L,G,X,y){let U=y.wireframe===!0,D=i[G.id];D===void 0&&(D={},i[G.id]=D);let A=L.isInstancedMesh===!0?L.id:0,z=D[A];z===void 0&&(z={},D[A]=z);let B=z[X.id];B===void 0&&(B={},z[X.id]=B);let H=B[U];return H===void 0&&(H=u(c()),B[U]=H),H}function u(L){let G=[],X=[],y=[];for(let U=0;U<t;U++)G[U]=0,X[U]=0,y[U]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:G,enabledAttributes:X,attributeDivisors:y,object:L,attributes:{},index:null}}function p(L,G,X,y){let U=r.attributes,D=G.attributes,A=0,z=X.getAttributes();for(let B in z)if(z[B].location>=0){let $=U[B],ne=D[B];if(ne===void 0&&(B==="instanceMatrix"&&L.instanceMatrix&&(ne=L.instanceMatrix),B==="instanceColor"&&L.instanceColor&&(ne=L.instanceColor)),$===void 0||$.attribute!==ne||ne&&$.data!==ne.data)return!0;A++}return r.attributesNum!==A||r.index!==y}function g(L,G,X,y){let U={},D=G.attributes,A=0,z=X.getAttributes();for(let B in z)if(z[B].location>=0){let $=D[B];$===void 0&&(B==="instanceMatrix"&&L.instanceMatrix&&($=L.instanceMatrix),B==="instanceColor"&&L.instanceColor&&($=L.instanceColor));let ne={};ne.attribute=$,$&&$.data&&(ne.data=$.data),U[B]=ne,A++}r.attributes=U,r.attributesNum=A,r.index=y}function b(){let L=r.newAttributes;for(let G=0,X=L.length;G<X;G++)L[G]=0}function d(L){m(L,0)}function m(L,G){let X=r.newAttributes,y=r.enabledAttributes,U=r.attributeDivisors;X[L]=1,y[L]===0&&(n.enableVertexAttribArray(L),y[L]=1),U[L]!==G&&(n.vertexAttribDivisor(L,G),U[L]=G)}function v(){let L=r.newAttributes,G=r.enabledAttributes;for(let X=0,y=G.length;X<y;X++)G[X]!==L[X]&&(n.disableVertexAttribArray(X),G[X]=0)}function C(L,G,X,y,U,D,A){A===!0?n.vertexAttribIPointer(L,G,X,U,D):n.vertexAttribPointer(L,G,X,y,U,D)}function S(L,G,X,y){b();let U=y.attributes,D=X.getAttributes(),A=G.defaultAttributeValues;for(let z in D){let B=D[z];if(B.location>=0){let H=U[z];if(H===void 0&&(z==="instanceMatrix"&&L.instanceMatrix&&(H=L.instanceMatrix),z==="instanceColor"&&L.instanceColor&&(H=L.instanceColor)),H!==void 0){let $=H.normalized,ne=H.itemSize,oe=e.get(H);if(oe===void 0)continue;let se=oe.buffer,_e=oe.type,me=oe.bytesPerElement,Ee=_e===n.INT||_e===n.UNSIGNED_INT||H.gpuType===Yc;if(H.isInterleavedBufferAttribute){let Se=H.data,Ze=Se.isInterleavedBuffer===!0?Se.stride:Se.itemSize,rt=H.offset;if(Se.isInstancedInterleavedBuffer||Se.isInstancedBufferAttribute){for(let Ye=0;Ye<B.locationSize;Ye++)m(B.location+Ye,Se.meshPerAttribute);L.isInstancedMesh!==!0&&y._maxInstanceCount===void 0&&(y._maxInstanceCount=Se.meshPerAttribute*Se.count)}else for(let Ye=0;Ye<B.locationSize;Ye++)d(B.location+Ye);n.bindBuffer(n.ARRAY_BUFFER,se);for(let Ye=0;Ye<B.locationSize;Ye++)C(B.location+Ye,ne/B.locationSize,_e,$,Ze*me,(rt+ne/B.locationSize*Ye)*me,Ee)}else{if(H.isInstancedBufferAttribute){for(let Se=0;Se<B.locationSize;Se++)m(B.location+Se,H.meshPerAttribute);L.isInstancedMesh!==!0&&y._maxInstanceCount===void 0&&(y._maxInstanceCount=H.meshPerAttribute*H.count)}else for(let Se=0;Se<B.locationSize;Se++)d(B.location+Se);n.bindBuffer(n.ARRAY_BUFFER,se);for(let Se=0;Se<B.locationSize;Se++)C(B.location+Se,ne/B.locationSize,_e,$,ne*me,ne/B.locationSize*Se*me,Ee)}}else if(A!==void 0){let $=A[z];if($!==void 0)switch($.length){case 2:n.vertexAttrib2fv(B.location,$);break;case 3:n.vertexAttrib3fv(B.location,$);break;case 4:n.vertexAttrib4fv(B.location,$);break;default:n.vertexAttrib1fv(B.location,$)}}}}v()}function P(){W();for(let L in i){let G=i[L];for(let X in G){let y=G[X];for(let U in y){let D=y[U];for(let A in D)h(D[A].object),delete D[A];delete y[U]}}delete i[L]}}function T(L){if(i[L.id]===void 0)return;let G=i[L.id];for(let X in G){let y=G[X];for(let U in y){let D=y[U];for(let A in D)h(D[A].object),delete D[A];delete y[U]}}delete i[L.id]}function _(L){for(let G in i){let X=i[G];for(let y in X){let U=X[y];if(U[L.id]===void 0)continue;let D=U[L.id];for(let A in D)h(D[A].object),delete D[A];delete U[L.id]}}}function R(L){for(let G in i){let X=i[G],y=L.isInstancedMesh===!0?L.id:0,U=X[y];if(U!==void 0){for(let D in U){let A=U[D];for(let z in A)h(A[z].object),delete A[z];delete U[D]}delete X[y],Object.keys(X).length===0&&delete i[G]}}}function W(){O(),o=!0,r!==s&&(r=s,l(r.object))}function O(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:a,reset:W,resetDefaultState:O,dispose:P,releaseStatesOfGeometry:T,releaseStatesOfObject:R,releaseStatesOfProgram:_,initAttributes:b,enableAttribute:d,disableUnusedAttributes:v}}function _b(n,e,t){let i;function s(c){i=c}function r(c,l){n.drawArrays(i,c,l),t.update(l,i,1)}function o(c,l,h){h!==0&&(n.drawArraysInstanced(i,c,l,h),t.update(l,i,h))}function a(c,l,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,c,0,l,0,h);let u=0;for(let p=0;p<h;p++)u+=l[p];t.update(u,i,1)}this.setMode=s,this.render=r,this.renderInstances=o,this.renderMultiDraw=a}function xb(n,e,t,i){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){let _=e.get("EXT_texture_filter_anisotropic");s=n.getParameter(_.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function o(_){return!(_!==Yi&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function a(_){let R=_===qi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(_!==bi&&_!==Xi&&!R&&i.convert(_)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function c(_){if(_==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";_="mediump"}return _==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=t.precision!==void 0?t.precision:"highp",h=c(l);h!==l&&(et("WebGLRenderer:",l,"not supported, using",h,"instead."),l=h);let f=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),u=t.logarithmicDepthBuffer===!0&&f===!1;t.reversedDepthBuffer===!0&&f===!1&&et("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&f===!0&&et("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let p=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),g=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),b=n.getParameter(n.MAX_TEXTURE_SIZE),d=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),m=n.getParameter(n.MAX_VERTEX_ATTRIBS),v=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),C=n.getParameter(n.MAX_VARYING_VECTORS),S=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),P=n.getParameter(n.MAX_SAMPLES),T=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:c,textureFormatReadable:o,textureTypeReadable:a,precision:l,logarithmicDepthBuffer:u,reversedDepthBuffer:f,maxTextures:p,maxVertexTextures:g,maxTextureSize:b,maxCubemapSize:d,maxAttributes:m,maxVertexUniforms:v,maxVaryings:C,maxFragmentUniforms:S,maxSamples:P,samples:T}}function yb(n){let e=this,t=null,i=0,s=!1,r=!1,o=new xi,a=new lt,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(f,u){let p=f.length!==0||u||i!==0||s;return s=u,i=f.length,p},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(f,u){t=h(f,u,0)},this.setState=function(f,u,p){let g=f.clippingPlanes,b=f.clipIntersection,d=f.clipShadows,m=n.get(f);if(!s||g===null||g.length===0||r&&!d)r?h(null):l();else{let v=r?0:i,C=v*4,S=m.clippingState||null;c.value=S,S=h(g,u,C,p);for(let P=0;P!==C;++P)S[P]=t[P];m.clippingState=S,this.numIntersection=b?this.numPlanes:0,this.numPlanes+=v}};function l(){c.value!==t&&(c.value=t,c.needsUpdate=i>0),e.numPlanes=i,e.numIntersection=0}function h(f,u,p,g){let b=f!==null?f.length:0,d=null;if(b!==0){if(d=c.value,g!==!0||d===null){let m=p+b*4,v=u.matrixWorldInverse;a.getNormalMatrix(v),(d===null||d.length<m)&&(d=new Float32Array(m));for(let C=0,S=p;C!==b;++C,S+=4)o.copy(f[C]).applyMatrix4(v,a),o.normal.toArray(d,S),d[S+3]=o.constant}c.value=d,c.needsUpdate=!0}return e.numPlanes=b,e.numIntersection=0,d}}var Za=class extends Si{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let i={width:e,height:e,depth:1},s=[i,i,i,i,i,i];this.texture=new Pa(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new Po(5,5,5),r=new cs({name:"CubemapFromEquirect",uniforms:Lr(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:ei,blending:Rr});r.uniforms.tEquirect.value=t;let o=new ls(s,r),a=t.minFilter;return t.minFilter===Ds&&(t.minFilter=Qn),new Io(1,10,this).update(e,o),t.minFilter=a,o.geometry.dispose(),o.material.dispose(),this}clear(e,t=!0,i=!0,s=!0){let r=e.getRenderTarget();for(let o=0;o<6;o++)e.setRenderTarget(this,o),e.clear(t,i,s);e.setRenderTarget(r)}},u0=256,vb=3,Sb=20,N0=256,U0=16,Mb=3,bb=new ee,wb=new _t,Ih=class n{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new Io(1,10,null),this._boxMesh=new ls(new Po(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,i=.1,s=100,r={}){let{size:o=256,position:a=bb}=r,c=this._renderer;this._setSize(o);let l=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);let f=c.autoClear,u=c.autoClearColor,p=c.autoClearDepth,g=c.autoClearStencil,b=e.background;c.autoClear=!0,c.autoClearColor=!0,c.autoClearDepth=!0,c.autoClearStencil=!0,b===null&&(e.background=c.getClearColor(wb));let d=new Io(i,s,h);return d.position.copy(a),d.update(c,e),c.autoClear=f,c.autoClearColor=u,c.autoClearDepth=p,c.autoClearStencil=g,e.background=b,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(l,t)),this._applyPMREM(l),l}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=p0(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=d0(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(u0,td(e))}_fromTexture(e,t){e.mapping===Pr||e.mapping===Uo?this._setSize(e.image.length===0?u0:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);let i=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(i),i}_allocateTarget(){let e=this._cubeSize,t=f0(e,!1,!1),i=Math.log2(e)-vb;for(let s=0;s<=i;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){let t=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==t||e&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=f0(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,i){let s=this._boxMesh,r=this._cubeCamera;s.material=i,r.renderTarget=e,r.activeMipmapLevel=t;let o=e.width>>t;e.viewport.set(0,0,o,o),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Pr||e.mapping===Uo?(this._cubemapMaterial===null&&(this._cubemapMaterial=p0()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=d0()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=Eb(),this._integrationMaterial=Tb());let t=this._cubeSize,i=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;let r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/U0);for(let o=0;o<=i;o++){let a=n.lodToRoughness(o,i);if(o>i-Mb)r.roughness.value=a,this._renderCube(e,o,this._integrationMaterial);else{let c=a>0?Math.log2(t)+.5*Math.log2(6/(N0*Math.pow(a,4)))+.5:0;s.roughness.value=a,s.lodBias.value=c,this._renderCube(e,o,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=Ab());let i=this._blurMaterial,s=i.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,i),s.envMap.value=e.texture,this._renderCube(r,0,i)}};function f0(n,e,t){return new Za(n,{minFilter:Ds,generateMipmaps:e,type:qi,colorSpace:ya,depthBuffer:t})}function Ja(n,e,t){return new cs({name:n,uniforms:e,vertexShader:xt.cube_vert,fragmentShader:t,side:ei,blending:Rr,depthTest:!1,depthWrite:!1})}function Eb(){return Ja("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${N0}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function Tb(){return Ja("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:U0}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function Ab(){return Ja("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${Sb}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function d0(){return Ja("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function p0(){return Ja("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function Rb(n){let e=new WeakMap,t=new WeakMap,i=null;function s(u,p=!1){return u==null?null:p?o(u):r(u)}function r(u){if(u&&u.isTexture){let p=u.mapping;if(p===Wc||p===Xc)if(e.has(u)){let g=e.get(u).texture;return a(g,u.mapping)}else{let g=u.image;if(g&&g.height>0){let b=new Za(g.height);return b.fromEquirectangularTexture(n,u),e.set(u,b),u.addEventListener("dispose",l),a(b.texture,u.mapping)}else return null}}return u}function o(u){if(u&&u.isTexture&&u.isPMREMTexture!==!0){let p=u.mapping,g=p===Wc||p===Xc,b=p===Pr||p===Uo;if(g||b){let d=t.get(u),m=d!==void 0?d.texture.pmremVersion:0;if(u.isRenderTargetTexture&&u.pmremVersion!==m)return i===null&&(i=new Ih(n)),d=g?i.fromEquirectangular(u,d):i.fromCubemap(u,d),d.texture.pmremVersion=u.pmremVersion,t.set(u,d),d.texture;if(d!==void 0)return d.texture;{let v=u.image;return g&&v&&v.height>0||b&&v&&c(v)?(i===null&&(i=new Ih(n)),d=g?i.fromEquirectangular(u):i.fromCubemap(u),d.texture.pmremVersion=u.pmremVersion,t.set(u,d),u.addEventListener("dispose",h),d.texture):null}}}return u}function a(u,p){return p===Wc?u.mapping=Pr:p===Xc&&(u.mapping=Uo),u}function c(u){let p=0,g=6;for(let b=0;b<g;b++)u[b]!==void 0&&p++;return p===g}function l(u){let p=u.target;p.removeEventListener("dispose",l);let g=e.get(p);g!==void 0&&(e.delete(p),g.dispose())}function h(u){let p=u.target;p.removeEventListener("dispose",h);let g=t.get(p);g!==void 0&&(t.delete(p),g.dispose())}function f(){e=new WeakMap,t=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:s,dispose:f}}function Cb(n){let e={};function t(i){if(e[i]!==void 0)return e[i];let s=n.getExtension(i);return e[i]=s,s}return{has:function(i){return t(i)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(i){let s=t(i);return s===null&&ma("WebGLRenderer: "+i+" extension not supported."),s}}}function Pb(n,e,t,i){let s={},r=new WeakMap,o=new FinalizationRegistry(g=>delete s[g]);function a(g){c(g.target)}function c(g){g.index!==null&&e.remove(g.index);for(let d in g.attributes)e.remove(g.attributes[d]);g.removeEventListener("dispose",a),delete s[g.id],o.unregister(g);let b=r.get(g);b&&(e.remove(b),r.delete(g)),i.releaseStatesOfGeometry(g),g.isInstancedBufferGeometry===!0&&delete g._maxInstanceCount,t.memory.geometries--}function l(g,b){return s[b.id]!==void 0||(b.addEventListener("dispose",a),s[b.id]=new WeakRef(b),o.register(b,b.id,b),t.memory.geometries++),b}function h(g){let b=g.attributes;for(let d in b)e.update(b[d],n.ARRAY_BUFFER)}function f(g){let b=g.index,d=g.attributes.position,m=0;if(d===void 0)return;let v=b!==null?b.array.length:d.array.length/3-1,C=d.count>=65535?Aa:Ta,S=new C(Math.ceil(v/3)*6,1),P=S.array;if(b!==null){let _=b.array;m=b.version;for(let R=0,W=0;R<v;R+=3){let O=_[R+0],L=_[R+1],G=_[R+2];P[W++]=O,P[W++]=L,P[W++]=L,P[W++]=G,P[W++]=G,P[W++]=O}}else{m=d.version;for(let _=0,R=0;_<v;_+=3){let W=_+0,O=_+1,L=_+2;P[R++]=W,P[R++]=O,P[R++]=O,P[R++]=L,P[R++]=L,P[R++]=W}}S.version=m;let T=r.get(g);T&&e.remove(T),r.set(g,S)}function u(g){let b=r.get(g);if(b){let d=g.index;d!==null&&b.version<d.version&&f(g)}else f(g);return r.get(g)}function p(){for(let g in s){let b=s[g].deref();b!==void 0&&c(b)}}return{get:l,update:h,getWireframeAttribute:u,dispose:p}}function Ib(n,e,t){let i;function s(f){i=f}let r,o;function a(f){r=f.type,o=f.bytesPerElement}function c(f,u){n.drawElements(i,u,r,f*o),t.update(u,i,1)}function l(f,u,p){p!==0&&(n.drawElementsInstanced(i,u,r,f*o,p),t.update(u,i,p))}function h(f,u,p){if(p===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,u,0,r,f,0,p);let b=0;for(let d=0;d<p;d++)b+=u[d];t.update(b,i,1)}this.setMode=s,this.setIndex=a,this.render=c,this.renderInstances=l,this.renderMultiDraw=h}function Lb(n){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function i(r,o,a){switch(t.calls++,o){case n.TRIANGLES:t.triangles+=a*(r/3);break;case n.LINES:t.lines+=a*(r/2);break;case n.LINE_STRIP:t.lines+=a*(r-1);break;case n.LINE_LOOP:t.lines+=a*r;break;case n.POINTS:t.points+=a*r;break;default:at("WebGLInfo: Unknown draw mode:",o);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:i}}function Db(n,e,t){let i=new WeakMap,s=new rn;function r(o,a,c){let l=o.morphTargetInfluences,h=a.morphAttributes.position||a.morphAttributes.normal||a.morphAttributes.color,f=h!==void 0?h.length:0,u=i.get(a);if(u===void 0||u.count!==f){let W=function(){_.dispose(),i.delete(a),a.removeEventListener("dispose",W)};u!==void 0&&u.texture.dispose();let p=a.morphAttributes.position!==void 0,g=a.morphAttributes.normal!==void 0,b=a.morphAttributes.color!==void 0,d=a.morphAttributes.position||[],m=a.morphAttributes.normal||[],v=a.morphAttributes.color||[],C=0;p===!0&&(C=1),g===!0&&(C=2),b===!0&&(C=3);let S=a.attributes.position.count*C,P=1;S>e.maxTextureSize&&(P=Math.ceil(S/e.maxTextureSize),S=e.maxTextureSize);let T=new Float32Array(S*P*4*f),_=new ba(T,S,P,f);_.type=Xi,_.needsUpdate=!0;let R=C*4;for(let O=0;O<f;O++){let L=d[O],G=m[O],X=v[O],y=S*P*4*O;for(let U=0;U<L.count;U++){let D=U*R;p===!0&&(s.fromBufferAttribute(L,U),T[y+D+0]=s.x,T[y+D+1]=s.y,T[y+D+2]=s.z,T[y+D+3]=0),g===!0&&(s.fromBufferAttribute(G,U),T[y+D+4]=s.x,T[y+D+5]=s.y,T[y+D+6]=s.z,T[y+D+7]=0),b===!0&&(s.fromBufferAttribute(X,U),T[y+D+8]=s.x,T[y+D+9]=s.y,T[y+D+10]=s.z,T[y+D+11]=X.itemSize===4?s.w:1)}}u={count:f,texture:_,size:new ft(S,P)},i.set(a,u),a.addEventListener("dispose",W)}if(o.isInstancedMesh===!0&&o.morphTexture!==null)c.getUniforms().setValue(n,"morphTexture",o.morphTexture,t);else{let p=0;for(let b=0;b<l.length;b++)p+=l[b];let g=a.morphTargetsRelative?1:1-p;c.getUniforms().setValue(n,"morphTargetBaseInfluence",g),c.getUniforms().setValue(n,"morphTargetInfluences",l)}c.getUniforms().setValue(n,"morphTargetsTexture",u.texture,t),c.getUniforms().setValue(n,"morphTargetsTextureSize",u.size)}return{update:r}}function Nb(n,e,t,i,s){let r=new WeakMap;function o(l){let h=s.render.frame,f=l.geometry,u=e.get(l,f);if(r.get(u)!==h&&(e.update(u),r.set(u,h)),l.isInstancedMesh&&(l.hasEventListener("dispose",c)===!1&&l.addEventListener("dispose",c),r.get(l)!==h&&(t.update(l.instanceMatrix,n.ARRAY_BUFFER),l.instanceColor!==null&&t.update(l.instanceColor,n.ARRAY_BUFFER),r.set(l,h))),l.isSkinnedMesh){let p=l.skeleton;r.get(p)!==h&&(p.update(),r.set(p,h))}return u}function a(){r=new WeakMap}function c(l){let h=l.target;h.removeEventListener("dispose",c),i.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:o,dispose:a}}var Ub={[Df]:"LINEAR_TONE_MAPPING",[Nf]:"REINHARD_TONE_MAPPING",[Uf]:"CINEON_TONE_MAPPING",[Ff]:"ACES_FILMIC_TONE_MAPPING",[Bf]:"AGX_TONE_MAPPING",[kf]:"NEUTRAL_TONE_MAPPING",[Of]:"CUSTOM_TONE_MAPPING"};function Fb(n,e,t,i,s,r){let o=new Si(e,t,{type:n,depthBuffer:s,stencilBuffer:r,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),a=null,c=null,l=null,h=new ii;h.setAttribute("position",new On([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new On([0,2,0,0,2,0],2));let f=new Rc({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),u=new ls(h,f),p=new Vc(-1,1,1,-1,0,1),g=null,b=null,d=!1,m,v=null,C=[],S=!1;this.setSize=function(P,T){o.setSize(P,T),a!==null&&a.setSize(P,T),c!==null&&c.setSize(P,T);for(let _=0;_<C.length;_++){let R=C[_];R.setSize&&R.setSize(P,T)}},this.setEffects=function(P){C=P,S=C.length>0&&C[0].isRenderPass===!0;let T=o.width,_=o.height;C.length>0&&a===null&&(a=new Si(T,_,{type:qi,depthBuffer:!1,stencilBuffer:!1}),c=new Si(T,_,{type:qi,depthBuffer:!1,stencilBuffer:!1}));let R=s===!0&&C.some(W=>W.needsDepthTexture===!0);R!==(o.depthTexture!==null)&&(R===!0&&l===null&&(l=new Ls(T,_),r===!0&&(l.format=Ns,l.type=Ir)),o.dispose(),o.depthTexture=R?l:null,o.resolveDepthBuffer=R,o.storeMultisampledDepthBuffer=R);for(let W=0;W<C.length;W++){let O=C[W];O.setSize&&O.setSize(T,_),R&&O.needsDepthTexture===!0&&O.setDepthTexture&&O.setDepthTexture(l)}},this.begin=function(P,T){if(d||P.toneMapping===us&&C.length===0)return!1;if(v=T,T!==null){let _=T.width,R=T.height;(o.width!==_||o.height!==R)&&this.setSize(_,R)}return S===!1&&P.setRenderTarget(o),m=P.toneMapping,P.toneMapping=us,!0},this.hasRenderPass=function(){return S},this.end=function(P,T){P.toneMapping=m,d=!0;let _=o,R=a;for(let W=0;W<C.length;W++){let O=C[W];O.enabled!==!1&&(O.render(P,R,_,T),O.needsSwap!==!1&&(_=R,R=R===a?c:a))}if(g!==P.outputColorSpace||b!==P.toneMapping){g=P.outputColorSpace,b=P.toneMapping,f.defines={},At.getTransfer(g)===kt&&(f.defines.SRGB_TRANSFER="");let W=Ub[b];W&&(f.defines[W]=""),f.needsUpdate=!0}f.uniforms.tDiffuse.value=_.texture,P.setRenderTarget(v),P.render(u,p),v=null,d=!1},this.isCompositing=function(){return d},this.dispose=function(){o.dispose(),a!==null&&a.dispose(),c!==null&&c.dispose(),h.dispose(),f.dispose()}}var F0=new ti,O0=new Ls(1,1),B0=new Ia(1),k0=new ba,z0=new Sc,V0=new Pa,m0=[],g0=[],_0=new Float32Array(16),x0=new Float32Array(9),y0=new Float32Array(4);function ko(n,e,t){let i=n[0];if(i<=0||i>0)return n;let s=e*t,r=m0[s];if(r===void 0&&(r=new Float32Array(s),m0[s]=r),e!==0){i.toArray(r,0);for(let o=1,a=0;o!==e;++o)a+=t,n[o].toArray(r,a)}return r}function An(n,e){if(n.length!==e.length)return!1;for(let t=0,i=n.length;t<i;t++)if(n[t]!==e[t])return!1;return!0}function Rn(n,e){for(let t=0,i=e.length;t<i;t++)n[t]=e[t]}function Dh(n,e){let t=g0[e];t===void 0&&(t=new Int32Array(e),g0[e]=t);for(let i=0;i!==e;++i)t[i]=n.allocateTextureUnit();return t}function Ob(n,e){let t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function Bb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(An(t,e))return;n.uniform2fv(this.addr,e),Rn(t,e)}}function kb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(An(t,e))return;n.uniform3fv(this.addr,e),Rn(t,e)}}function zb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(An(t,e))return;n.uniform4fv(this.addr,e),Rn(t,e)}}function Vb(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(An(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),Rn(t,e)}else{if(An(t,i))return;y0.set(i),n.uniformMatrix2fv(this.addr,!1,y0),Rn(t,i)}}function Hb(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(An(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),Rn(t,e)}else{if(An(t,i))return;x0.set(i),n.uniformMatrix3fv(this.addr,!1,x0),Rn(t,i)}}function Gb(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(An(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),Rn(t,e)}else{if(An(t,i))return;_0.set(i),n.uniformMatrix4fv(this.addr,!1,_0),Rn(t,i)}}function Wb(n,e){let t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function Xb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(An(t,e))return;n.uniform2iv(this.addr,e),Rn(t,e)}}function qb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(An(t,e))return;n.uniform3iv(this.addr,e),Rn(t,e)}}function Yb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(An(t,e))return;n.uniform4iv(this.addr,e),Rn(t,e)}}function $b(n,e){let t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function Zb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(An(t,e))return;n.uniform2uiv(this.addr,e),Rn(t,e)}}function Jb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(An(t,e))return;n.uniform3uiv(this.addr,e),Rn(t,e)}}function Kb(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(An(t,e))return;n.uniform4uiv(this.addr,e),Rn(t,e)}}function Nh(n){return n.version===0&&(n.compareFunction=Kf,n.needsUpdate=!0),n}function jb(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_2D_SHADOW?r=Nh(O0):r=F0,t.setTexture2D(e||r,s)}function Qb(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture3D(e||z0,s)}function ew(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_CUBE_SHADOW?r=Nh(B0):r=V0,t.setTextureCube(e||r,s)}function tw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture2DArray(e||k0,s)}function nw(n){switch(n){case 5126:return Ob;case 35664:return Bb;case 35665:return kb;case 35666:return zb;case 35674:return Vb;case 35675:return Hb;case 35676:return Gb;case 5124:case 35670:return Wb;case 35667:case 35671:return Xb;case 35668:case 35672:return qb;case 35669:case 35673:return Yb;case 5125:return $b;case 36294:return Zb;case 36295:return Jb;case 36296:return Kb;case 35678:case 36198:case 36298:case 36306:case 35682:return jb;case 35679:case 36299:case 36307:return Qb;case 35680:case 36300:case 36308:case 36293:return ew;case 36289:case 36303:case 36311:case 36292:return tw}}function iw(n,e){n.uniform1fv(this.addr,e)}function sw(n,e){let t=ko(e,this.size,2);n.uniform2fv(this.addr,t)}function rw(n,e){let t=ko(e,this.size,3);n.uniform3fv(this.addr,t)}function ow(n,e){let t=ko(e,this.size,4);n.uniform4fv(this.addr,t)}function aw(n,e){let t=ko(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function lw(n,e){let t=ko(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function cw(n,e){let t=ko(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function hw(n,e){n.uniform1iv(this.addr,e)}function uw(n,e){n.uniform2iv(this.addr,e)}function fw(n,e){n.uniform3iv(this.addr,e)}function dw(n,e){n.uniform4iv(this.addr,e)}function pw(n,e){n.uniform1uiv(this.addr,e)}function mw(n,e){n.uniform2uiv(this.addr,e)}function gw(n,e){n.uniform3uiv(this.addr,e)}function _w(n,e){n.uniform4uiv(this.addr,e)}function xw(n,e,t){let i=this.cache,s=e.length,r=Dh(t,s);An(i,r)||(n.uniform1iv(this.addr,r),Rn(i,r));let o;this.type===n.SAMPLER_2D_SHADOW?o=Nh(O0):o=F0;for(let a=0;a!==s;++a)t.setTexture2D(e[a]||o,r[a])}function yw(n,e,t){let i=this.cache,s=e.length,r=Dh(t,s);An(i,r)||(n.uniform1iv(this.addr,r),Rn(i,r));for(let o=0;o!==s;++o)t.setTexture3D(e[o]||z0,r[o])}function vw(n,e,t){let i=this.cache,s=e.length,r=Dh(t,s);An(i,r)||(n.uniform1iv(this.addr,r),Rn(i,r));let o;this.type===n.SAMPLER_CUBE_SHADOW?o=Nh(B0):o=V0;for(let a=0;a!==s;++a)t.setTextureCube(e[a]||o,r[a])}function Sw(n,e,t){let i=this.cache,s=e.length,r=Dh(t,s);An(i,r)||(n.uniform1iv(this.addr,r),Rn(i,r));for(let o=0;o!==s;++o)t.setTexture2DArray(e[o]||k0,r[o])}function Mw(n){switch(n){case 5126:return iw;case 35664:return sw;case 35665:return rw;case 35666:return ow;case 35674:return aw;case 35675:return lw;case 35676:return cw;case 5124:case 35670:return hw;case 35667:case 35671:return uw;case 35668:case 35672:return fw;case 35669:case 35673:return dw;case 5125:return pw;case 36294:return mw;case 36295:return gw;case 36296:return _w;case 35678:case 36198:case 36298:case 36306:case 35682:return xw;case 35679:case 36299:case 36307:return yw;case 35680:case 36300:case 36308:case 36293:return vw;case 36289:case 36303:case 36311:case 36292:return Sw}}var md=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.setValue=nw(t.type)}},gd=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=Mw(t.type)}},_d=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,i){let s=this.seq;for(let r=0,o=s.length;r!==o;++r){let a=s[r];a.setValue(e,t[a.id],i)}}},dd=/(\w+)(\])?(\[|\.)?/g;function v0(n,e){n.seq.push(e),n.map[e.id]=e}function bw(n,e,t){let i=n.name,s=i.length;for(dd.lastIndex=0;;){let r=dd.exec(i),o=dd.lastIndex,a=r[1],c=r[2]==="]",l=r[3];if(c&&(a=a|0),l===void 0||l==="["&&o+2===s){v0(t,l===void 0?new md(a,n,e):new gd(a,n,e));break}else{let f=t.map[a];f===void 0&&(f=new _d(a),v0(t,f)),t=f}}}var Bo=class{constructor(e,t){this.seq=[],this.map={};let i=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let o=0;o<i;++o){let a=e.getActiveUniform(t,o),c=e.getUniformLocation(t,a.name);bw(a,c,this)}let s=[],r=[];for(let o of this.seq)o.type===e.SAMPLER_2D_SHADOW||o.type===e.SAMPLER_CUBE_SHADOW||o.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(o):r.push(o);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,i,s){let r=this.map[t];r!==void 0&&r.setValue(e,i,s)}setOptional(e,t,i){let s=t[i];s!==void 0&&this.setValue(e,i,s)}static upload(e,t,i,s){for(let r=0,o=t.length;r!==o;++r){let a=t[r],c=i[a.id];c.needsUpdate!==!1&&a.setValue(e,c.value,s)}}static seqWithValue(e,t){let i=[];for(let s=0,r=e.length;s!==r;++s){let o=e[s];o.id in t&&i.push(o)}return i}};function S0(n,e,t){let i=n.createShader(e);return n.shaderSource(i,t),n.compileShader(i),i}var ww=37297,Ew=0;function Tw(n,e){let t=n.split(`
`),i=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let o=s;o<r;o++){let a=o+1;i.push(`${a===e?">":" "} ${a}: ${t[o]}`)}return i.join(`
`)}var M0=new lt;function Aw(n){At._getMatrix(M0,At.workingColorSpace,n);let e=`mat3( ${M0.elements.map(t=>t.toFixed(4))} )`;switch(At.getTransfer(n)){case va:return[e,"LinearTransferOETF"];case kt:return[e,"sRGBTransferOETF"];default:return et("WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function b0(n,e,t){let i=n.getShaderParameter(e,n.COMPILE_STATUS),r=(n.getShaderInfoLog(e)||"").trim();if(i&&r==="")return"";let o=/ERROR: 0:(\d+)/.exec(r);if(o){let a=parseInt(o[1]);return t.toUpperCase()+`

`+r+`

`+Tw(n.getShaderSource(e),a)}else return r}function Rw(n,e){let t=Aw(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}var Cw={[Df]:"Linear",[Nf]:"Reinhard",[Uf]:"Cineon",[Ff]:"ACESFilmic",[Bf]:"AgX",[kf]:"Neutral",[Of]:"Custom"};function Pw(n,e){let t=Cw[e];return t===void 0?(et("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var Ph=new ee;function Iw(){At.getLuminanceCoefficients(Ph);let n=Ph.x.toFixed(4),e=Ph.y.toFixed(4),t=Ph.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function Lw(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter($a).join(`
`)}function Dw(n){let e=[];for(let t in n){let i=n[t];i!==!1&&e.push("#define "+t+" "+i)}return e.join(`
`)}function Nw(n,e){let t={},i=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let s=0;s<i;s++){let r=n.getActiveAttrib(e,s),o=r.name,a=1;r.type===n.FLOAT_MAT2&&(a=2),r.type===n.FLOAT_MAT3&&(a=3),r.type===n.FLOAT_MAT4&&(a=4),t[o]={type:r.type,location:n.getAttribLocation(e,o),locationSize:a}}return t}function $a(n){return n!==""}function w0(n,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function E0(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var Uw=/^[ \t]*#include +<([\w\d./]+)>/gm;function xd(n){return n.replace(Uw,Fw)}function Fw(n,e){let t=xt[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return xd(t)}var Ow=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function T0(n){return n.replace(Ow,Bw)}function Bw(n,e,t,i){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=i.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function A0(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}var kw={[ka]:"SHADOWMAP_TYPE_PCF",[Do]:"SHADOWMAP_TYPE_VSM"};function zw(n){return kw[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}var Vw={[Uo]:"ENVMAP_MODE_REFRACTION"};function Hw(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":Vw[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}var Gw={[Lf]:"ENVMAP_BLENDING_MULTIPLY",[Gg]:"ENVMAP_BLENDING_MIX",[Wg]:"ENVMAP_BLENDING_ADD"};function Ww(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":Gw[n.combine]||"ENVMAP_BLENDING_NONE"}function Xw(n,e,t,i){let s=n.getContext(),r=t.defines,o=t.vertexShader,a=t.fragmentShader,c=zw(t),l=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=Hw(t),f=Ww(t),u=Lw(t),p=Dw(r),g=s.createProgram(),b,d,m=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(b=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p].filter($a).join(`
`),b.length>0&&(b+=`
`),d=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p].filter($a).join(`
`),d.length>0&&(d+=`
`)):(b=[A0(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+c:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter($a).join(`
`),d=[A0(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+l:"",t.envMap?"#define "+h:"",t.envMap?"#define "+f:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+c:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==us?"#define TONE_MAPPING":"",t.toneMapping!==us?xt.tonemapping_pars_fragment:"",t.toneMapping!==us?Pw("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",xt.colorspace_pars_fragment,Rw("linearToOutputTexel",t.outputColorSpace),Iw(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter($a).join(`
`)),o=xd(o),o=w0(o,t),o=E0(o,t),a=xd(a),a=w0(a,t),a=E0(a,t),o=T0(o),a=T0(a),t.isRawShaderMaterial!==!0&&(m=`#version 300 es
`,b=[u,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+b,d=["#define varying in",t.glslVersion===jf?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===jf?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+d);let v=m+b+o,C=m+d+a,S=S0(s,s.VERTEX_SHADER,v),P=S0(s,s.FRAGMENT_SHADER,C);s.attachShader(g,S),s.attachShader(g,P),t.index0AttributeName!==void 0?s.bindAttribLocation(g,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(g,0,"position"),s.linkProgram(g);function T(O){if(n.debug.checkShaderErrors){let L=s.getProgramInfoLog(g)||"",G=s.getShaderInfoLog(S)||"",X=s.getShaderInfoLog(P)||"",y=L.trim(),U=G.trim(),D=X.trim(),A=!0,z=!0;if(s.getProgramParameter(g,s.LINK_STATUS)===!1)if(A=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(s,g,S,P);else{let B=b0(s,S,"vertex"),H=b0(s,P,"fragment");at("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(g,s.VALIDATE_STATUS)+`

Material Name: `+O.name+`
Material Type: `+O.type+`

Program Info Log: `+y+`
`+B+`
`+H)}else y!==""?et("WebGLProgram: Program Info Log:",y):(U===""||D==="")&&(z=!1);z&&(O.diagnostics={runnable:A,programLog:y,vertexShader:{log:U,prefix:b},fragmentShader:{log:D,prefix:d}})}s.deleteShader(S),s.deleteShader(P),_=new Bo(s,g),R=Nw(s,g)}let _;this.getUniforms=function(){return _===void 0&&T(this),_};let R;this.getAttributes=function(){return R===void 0&&T(this),R};let W=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return W===!1&&(W=s.getProgramParameter(g,ww)),W},this.destroy=function(){i.releaseStatesOfProgram(this),s.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=Ew++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=S,this.fragmentShader=P,this}var qw=0,yd=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,i){let s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(i)===!1&&(s.add(i),i.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let i of t)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,i=t.get(e);return i===void 0&&(i=new Set,t.set(e,i)),i}_getShaderStage(e){let t=this.shaderCache,i=t.get(e);return i===void 0&&(i=new vd(e),t.set(e,i)),i}},vd=class{constructor(e){this.id=qw++,this.code=e,this.usedTimes=0}};function Yw(n){return n===lr||n===Xa||n===qa}function $w(n,e,t,i,s,r){let o=new wa,a=new yd,c=new Set,l=[],h=new Map,f=i.logarithmicDepthBuffer,u={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function p(_){return c.add(_),_===0?"uv":`uv${_}`}function g(_,R,W,O,L,G){let X=O.fog,y=L.geometry,U=_.isMeshStandardMaterial||_.isMeshLambertMaterial||_.isMeshPhongMaterial?O.environment:null,D=_.isMeshStandardMaterial||_.isMeshLambertMaterial&&!_.envMap||_.isMeshPhongMaterial&&!_.envMap,A=e.get(_.envMap||U,D),z=u[_.type],B=i.precision;_.precision!==null&&(B=i.getMaxPrecision(_.precision),B!==_.precision&&et("WebGLProgram.getParameters:",_.precision,"not supported, using",B,"instead."));let H=y.morphAttributes.position||y.morphAttributes.normal||y.morphAttributes.color,$=H!==void 0?H.length:0,ne=0;y.morphAttributes.position!==void 0&&(ne=1),y.morphAttributes.normal!==void 0&&(ne=2),y.morphAttributes.color!==void 0&&(ne=3);let oe,se,_e,me;if(z){let Le=ds[z];oe=Le.vertexShader,se=Le.fragmentShader}else{oe=_.vertexShader,se=_.fragmentShader;let Le=a.getVertexShaderStage(_),pt=a.getFragmentShaderStage(_);a.update(_,Le,pt),_e=Le.id,me=pt.id}let Ee=n.getRenderTarget(),Se=n.state.buffers.depth.getReversed(),Ze=L.isInstancedMesh===!0,rt=L.isBatchedMesh===!0,Ye=!!_.map,Ie=!!_.matcap,Ue=!!A,Ve=Ue&&A.isPMREMTexture===!0,yt=!!_.aoMap,Pt=!!_.lightMap,zt=!!_.bumpMap&&_.wireframe===!1,ct=!!_.normalMap,It=!!_.displacementMap,je=!!_.emissiveMap,dt=!!_.metalnessMap,mt=!!_.roughnessMap,bt=_.anisotropy>0,k=_.clearcoat>0,De=_.diffuseRoughness>0,tt=_.dispersion>0,ut=_.retroreflectivity>0,Ae=_.iridescence>0,Xt=_.sheen>0,$e=_.transmission>0,Qe=bt&&!!_.anisotropyMap,I=k&&!!_.clearcoatMap,M=k&&!!_.clearcoatNormalMap,J=k&&!!_.clearcoatRoughnessMap,pe=De&&!!_.diffuseRoughnessMap,ue=Ae&&!!_.iridescenceMap,Me=Ae&&!!_.iridescenceThicknessMap,be=Xt&&!!_.sheenColorMap,ae=Xt&&!!_.sheenRoughnessMap,ce=!!_.specularMap,xe=!!_.specularColorMap,V=!!_.specularIntensityMap,he=$e&&!!_.transmissionMap,le=$e&&!!_.thicknessMap,Re=!!_.gradientMap,ve=!!_.alphaMap,Te=_.alphaTest>0,Je=!!_.alphaHash,it=!!_.extensions,de=us;_.toneMapped&&(Ee===null||Ee.isXRRenderTarget===!0)&&(de=n.toneMapping);let We=Ve?A.isCompressedCubeTexture?A.image[0].mipmaps:A.mipmaps:null,st={shaderID:z,shaderType:_.type,shaderName:_.name,vertexShader:oe,fragmentShader:se,defines:_.defines,customVertexShaderID:_e,customFragmentShaderID:me,isRawShaderMaterial:_.isRawShaderMaterial===!0,glslVersion:_.glslVersion,precision:B,batching:rt,batchingColor:rt&&L._colorsTexture!==null,instancing:Ze,instancingColor:Ze&&L.instanceColor!==null,instancingMorph:Ze&&L.morphTexture!==null,outputColorSpace:Ee===null?n.outputColorSpace:Ee.isXRRenderTarget===!0?Ee.texture.colorSpace:At.workingColorSpace,alphaToCoverage:!!_.alphaToCoverage,map:Ye,matcap:Ie,envMap:Ue,envMapMode:Ue&&A.mapping,envMapPMREM:Ve,envMapMaxLod:Ve?We.length-1:null,envMapSize:Ve?We[0].width:null,aoMap:yt,lightMap:Pt,bumpMap:zt,normalMap:ct,displacementMap:It,emissiveMap:je,normalMapObjectSpace:ct&&_.normalMapType===Yg,normalMapTangentSpace:ct&&_.normalMapType===$f,packedNormalMap:ct&&_.normalMapType===$f&&Yw(_.normalMap.format),metalnessMap:dt,roughnessMap:mt,anisotropy:bt,anisotropyMap:Qe,clearcoat:k,clearcoatMap:I,clearcoatNormalMap:M,clearcoatRoughnessMap:J,diffuseRoughness:De,diffuseRoughnessMap:pe,dispersion:tt,retroreflection:ut,iridescence:Ae,iridescenceMap:ue,iridescenceThicknessMap:Me,sheen:Xt,sheenColorMap:be,sheenRoughnessMap:ae,specularMap:ce,specularColorMap:xe,specularIntensityMap:V,transmission:$e,transmissionMap:he,thicknessMap:le,gradientMap:Re,opaque:_.transparent===!1&&_.blending===No&&_.alphaToCoverage===!1,alphaMap:ve,alphaTest:Te,alphaHash:Je,combine:_.combine,mapUv:Ye&&p(_.map.channel),aoMapUv:yt&&p(_.aoMap.channel),lightMapUv:Pt&&p(_.lightMap.channel),bumpMapUv:zt&&p(_.bumpMap.channel),normalMapUv:ct&&p(_.normalMap.channel),displacementMapUv:It&&p(_.displacementMap.channel),emissiveMapUv:je&&p(_.emissiveMap.channel),metalnessMapUv:dt&&p(_.metalnessMap.channel),roughnessMapUv:mt&&p(_.roughnessMap.channel),anisotropyMapUv:Qe&&p(_.anisotropyMap.channel),clearcoatMapUv:I&&p(_.clearcoatMap.channel),clearcoatNormalMapUv:M&&p(_.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:J&&p(_.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:pe&&p(_.diffuseRoughnessMap.channel),iridescenceMapUv:ue&&p(_.iridescenceMap.channel),iridescenceThicknessMapUv:Me&&p(_.iridescenceThicknessMap.channel),sheenColorMapUv:be&&p(_.sheenColorMap.channel),sheenRoughnessMapUv:ae&&p(_.sheenRoughnessMap.channel),specularMapUv:ce&&p(_.specularMap.channel),specularColorMapUv:xe&&p(_.specularColorMap.channel),specularIntensityMapUv:V&&p(_.specularIntensityMap.channel),transmissionMapUv:he&&p(_.transmissionMap.channel),thicknessMapUv:le&&p(_.thicknessMap.channel),alphaMapUv:ve&&p(_.alphaMap.channel),vertexTangents:!!y.attributes.tangent&&(ct||bt),vertexNormals:!!y.attributes.normal,vertexColors:_.vertexColors,vertexAlphas:_.vertexColors===!0&&!!y.attributes.color&&y.attributes.color.itemSize===4,pointsUvs:L.isPoints===!0&&!!y.attributes.uv&&(Ye||ve),fog:!!X,useFog:_.fog===!0,fogExp2:!!X&&X.isFogExp2,flatShading:_.wireframe===!1&&(_.flatShading===!0||y.attributes.normal===void 0&&ct===!1&&(_.isMeshLambertMaterial||_.isMeshPhongMaterial||_.isMeshStandardMaterial||_.isMeshPhysicalMaterial)),sizeAttenuation:_.sizeAttenuation===!0,logarithmicDepthBuffer:f,reversedDepthBuffer:Se,skinning:L.isSkinnedMesh===!0,hasPositionAttribute:y.attributes.position!==void 0,morphTargets:y.morphAttributes.position!==void 0,morphNormals:y.morphAttributes.normal!==void 0,morphColors:y.morphAttributes.color!==void 0,morphTargetsCount:$,morphTextureStride:ne,numSunLights:R.sun.length,numDirLights:R.directional.length,numPointLights:R.point.length,numSpotLights:R.spot.length,numSpotLightMaps:R.spotLightMap.length,numRectAreaLights:R.rectArea.length,numHemiLights:R.hemi.length,numSunLightShadows:R.sunShadowMap.length,numDirLightShadows:R.directionalShadowMap.length,numPointLightShadows:R.pointShadowMap.length,numSpotLightShadows:R.spotShadowMap.length,numSpotLightShadowsWithMaps:R.numSpotLightShadowsWithMaps,numLightProbes:R.numLightProbes,numLightProbeGrids:G.filter(Le=>Le.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:_.dithering,shadowMapEnabled:n.shadowMap.enabled&&W.length>0,shadowMapType:n.shadowMap.type,toneMapping:de,decodeVideoTexture:Ye&&_.map.isVideoTexture===!0&&At.getTransfer(_.map.colorSpace)===kt,decodeVideoTextureEmissive:je&&_.emissiveMap.isVideoTexture===!0&&At.getTransfer(_.emissiveMap.colorSpace)===kt,premultipliedAlpha:_.premultipliedAlpha,doubleSided:_.side===hs,flipSided:_.side===ei,useDepthPacking:_.depthPacking>=0,depthPacking:_.depthPacking||0,index0AttributeName:_.index0AttributeName,extensionClipCullDistance:it&&_.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(it&&_.extensions.multiDraw===!0||rt)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:_.customProgramCacheKey()};return st.vertexUv1s=c.has(1),st.vertexUv2s=c.has(2),st.vertexUv3s=c.has(3),c.clear(),st}function b(_){let R=[];if(_.shaderID?R.push(_.shaderID):(R.push(_.customVertexShaderID),R.push(_.customFragmentShaderID)),_.defines!==void 0)for(let W in _.defines)R.push(W),R.push(_.defines[W]);return _.isRawShaderMaterial===!1&&(d(R,_),m(R,_),R.push(n.outputColorSpace)),R.push(_.customProgramCacheKey),R.join()}function d(_,R){_.push(R.precision),_.push(R.outputColorSpace),_.push(R.envMapMode),_.push(R.envMapPMREM),_.push(R.envMapMaxLod),_.push(R.envMapSize),_.push(R.mapUv),_.push(R.alphaMapUv),_.push(R.lightMapUv),_.push(R.aoMapUv),_.push(R.bumpMapUv),_.push(R.normalMapUv),_.push(R.displacementMapUv),_.push(R.emissiveMapUv),_.push(R.metalnessMapUv),_.push(R.roughnessMapUv),_.push(R.anisotropyMapUv),_.push(R.clearcoatMapUv),_.push(R.clearcoatNormalMapUv),_.push(R.clearcoatRoughnessMapUv),_.push(R.diffuseRoughnessMapUv),_.push(R.iridescenceMapUv),_.push(R.iridescenceThicknessMapUv),_.push(R.sheenColorMapUv),_.push(R.sheenRoughnessMapUv),_.push(R.specularMapUv),_.push(R.specularColorMapUv),_.push(R.specularIntensityMapUv),_.push(R.transmissionMapUv),_.push(R.thicknessMapUv),_.push(R.combine),_.push(R.fogExp2),_.push(R.sizeAttenuation),_.push(R.morphTargetsCount),_.push(R.numSunLights),_.push(R.numDirLights),_.push(R.numPointLights),_.push(R.numSpotLights),_.push(R.numSpotLightMaps),_.push(R.numHemiLights),_.push(R.numRectAreaLights),_.push(R.numSunLightShadows),_.push(R.numDirLightShadows),_.push(R.numPointLightShadows),_.push(R.numSpotLightShadows),_.push(R.numSpotLightShadowsWithMaps),_.push(R.numLightProbes),_.push(R.numLightProbeGrids),_.push(R.shadowMapType),_.push(R.toneMapping),_.push(R.numClippingPlanes),_.push(R.numClipIntersection),_.push(R.depthPacking)}function m(_,R){o.disableAll(),R.instancing&&o.enable(0),R.instancingColor&&o.enable(1),R.instancingMorph&&o.enable(2),R.matcap&&o.enable(3),R.envMap&&o.enable(4),R.normalMapObjectSpace&&o.enable(5),R.normalMapTangentSpace&&o.enable(6),R.clearcoat&&o.enable(7),R.iridescence&&o.enable(8),R.alphaTest&&o.enable(9),R.vertexColors&&o.enable(10),R.vertexAlphas&&o.enable(11),R.vertexUv1s&&o.enable(12),R.vertexUv2s&&o.enable(13),R.vertexUv3s&&o.enable(14),R.vertexTangents&&o.enable(15),R.anisotropy&&o.enable(16),R.alphaHash&&o.enable(17),R.batching&&o.enable(18),R.dispersion&&o.enable(19),R.retroreflection&&o.enable(24),R.diffuseRoughness&&o.enable(25),R.batchingColor&&o.enable(20),R.gradientMap&&o.enable(21),R.packedNormalMap&&o.enable(22),R.vertexNormals&&o.enable(23),_.push(o.mask),o.disableAll(),R.fog&&o.enable(0),R.useFog&&o.enable(1),R.flatShading&&o.enable(2),R.logarithmicDepthBuffer&&o.enable(3),R.reversedDepthBuffer&&o.enable(4),R.skinning&&o.enable(5),R.morphTargets&&o.enable(6),R.morphNormals&&o.enable(7),R.morphColors&&o.enable(8),R.premultipliedAlpha&&o.enable(9),R.shadowMapEnabled&&o.enable(10),R.doubleSided&&o.enable(11),R.flipSided&&o.enable(12),R.useDepthPacking&&o.enable(13),R.dithering&&o.enable(14),R.transmission&&o.enable(15),R.sheen&&o.enable(16),R.opaque&&o.enable(17),R.pointsUvs&&o.enable(18),R.decodeVideoTexture&&o.enable(19),R.decodeVideoTextureEmissive&&o.enable(20),R.alphaToCoverage&&o.enable(21),R.numLightProbeGrids>0&&o.enable(22),R.hasPositionAttribute&&o.enable(23),_.push(o.mask)}function v(_){let R=u[_.type],W;if(R){let O=ds[R];W=l0.clone(O.uniforms)}else W=_.uniforms;return W}function C(_,R){let W=h.get(R);return W!==void 0?++W.usedTimes:(W=new Xw(n,R,_,s),l.push(W),h.set(R,W)),W}function S(_){if(--_.usedTimes===0){let R=l.indexOf(_);l[R]=l[l.length-1],l.pop(),h.delete(_.cacheKey),_.destroy()}}function P(_){a.remove(_)}function T(){a.dispose()}return{getParameters:g,getProgramCacheKey:b,getUniforms:v,acquireProgram:C,releaseProgram:S,releaseShaderCache:P,programs:l,dispose:T}}function Zw(){let n=new WeakMap;function e(o){return n.has(o)}function t(o){let a=n.get(o);return a===void 0&&(a={},n.set(o,a)),a}function i(o){n.delete(o)}function s(o,a,c){n.get(o)[a]=c}function r(){n=new WeakMap}return{has:e,get:t,remove:i,update:s,dispose:r}}function Jw(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.materialVariant!==e.materialVariant?n.materialVariant-e.materialVariant:n.z!==e.z?n.z-e.z:n.id-e.id}function R0(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function C0(){let n=[],e=0,t=[],i=[],s=[];function r(){e=0,t.length=0,i.length=0,s.length=0}function o(u){let p=0;return u.isInstancedMesh&&(p+=2),u.isSkinnedMesh&&(p+=1),p}function a(u,p,g,b,d,m){let v=n[e];return v===void 0?(v={id:u.id,object:u,geometry:p,material:g,materialVariant:o(u),groupOrder:b,renderOrder:u.renderOrder,z:d,group:m},n[e]=v):(v.id=u.id,v.object=u,v.geometry=p,v.material=g,v.materialVariant=o(u),v.groupOrder=b,v.renderOrder=u.renderOrder,v.z=d,v.group=m),e++,v}function c(u,p,g,b,d,m,v){v.reversedDepth===!0&&(d=-d);let C=a(u,p,g,b,d,m);g.transmission>0?i.push(C):g.transparent===!0?s.push(C):t.push(C)}function l(u,p,g,b,d,m){let v=a(u,p,g,b,d,m);g.transmission>0?i.unshift(v):g.transparent===!0?s.unshift(v):t.unshift(v)}function h(u,p){t.length>1&&t.sort(u||Jw),i.length>1&&i.sort(p||R0),s.length>1&&s.sort(p||R0)}function f(){for(let u=e,p=n.length;u<p;u++){let g=n[u];if(g.id===null)break;g.id=null,g.object=null,g.geometry=null,g.material=null,g.group=null}}return{opaque:t,transmissive:i,transparent:s,init:r,push:c,unshift:l,finish:f,sort:h}}function Kw(){let n=new WeakMap;function e(i,s){let r=n.get(i),o;return r===void 0?(o=new C0,n.set(i,[o])):s>=r.length?(o=new C0,r.push(o)):o=r[s],o}function t(){n=new WeakMap}return{get:e,dispose:t}}function jw(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new ee,color:new _t};break;case"SpotLight":t={position:new ee,direction:new ee,color:new _t,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new ee,color:new _t,distance:0,decay:0};break;case"HemisphereLight":t={direction:new ee,skyColor:new _t,groundColor:new _t};break;case"RectAreaLight":t={color:new _t,position:new ee,halfWidth:new ee,halfHeight:new ee};break}return n[e.id]=t,t}}}function Qw(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ft};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ft};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ft,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}var eE=0;function tE(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function nE(n){let e=new jw,t=Qw(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)i.probe.push(new ee);let s=new ee,r=new nn,o=new nn;function a(l){let h=0,f=0,u=0;for(let G=0;G<9;G++)i.probe[G].set(0,0,0);let p=0,g=0,b=0,d=0,m=0,v=0,C=0,S=0,P=0,T=0,_=0,R=0,W=0,O=0;l.sort(tE);for(let G=0,X=l.length;G<X;G++){let y=l[G],U=y.color,D=y.intensity,A=y.distance,z=null;if(y.shadow&&y.shadow.map&&(y.shadow.map.texture.format===lr?z=y.shadow.map.texture:z=y.shadow.map.depthTexture||y.shadow.map.texture),y.isAmbientLight)h+=U.r*D,f+=U.g*D,u+=U.b*D;else if(y.isLightProbe){for(let B=0;B<9;B++)i.probe[B].addScaledVector(y.sh.coefficients[B],D);O++}else if(y.isSunLight){let B=e.get(y);if(B.color.copy(y.color).multiplyScalar(y.intensity),y.castShadow){let H=y.shadow,$=t.get(y);$.shadowIntensity=H.intensity,$.shadowBias=H.bias,$.shadowNormalBias=H.normalBias,$.shadowRadius=H.radius,$.shadowMapSize.copy(H.mapSize).multiply(H.getFrameExtents()),i.sunShadow[g]=$,i.sunShadowMap[g]=z;let ne=H.getViewportCount();for(let oe=0;oe<ne;oe++)i.sunShadowMatrix[b+oe]=H.getMatrix(oe),i.sunShadowCascade[b+oe]=H._cascadeData[oe];b+=ne,g++}i.sun[p]=B,p++}else if(y.isDirectionalLight){let B=e.get(y);if(B.color.copy(y.color).multiplyScalar(y.intensity),y.castShadow){let H=y.shadow,$=t.get(y);$.shadowIntensity=H.intensity,$.shadowBias=H.bias,$.shadowNormalBias=H.normalBias,$.shadowRadius=H.radius,$.shadowMapSize=H.mapSize,i.directionalShadow[d]=$,i.directionalShadowMap[d]=z,i.directionalShadowMatrix[d]=y.shadow.matrix,P++}i.directional[d]=B,d++}else if(y.isSpotLight){let B=e.get(y);B.position.setFromMatrixPosition(y.matrixWorld),B.color.copy(U).multiplyScalar(D),B.distance=A,B.coneCos=Math.cos(y.angle),B.penumbraCos=Math.cos(y.angle*(1-y.penumbra)),B.decay=y.decay,i.spot[v]=B;let H=y.shadow;if(y.map&&(i.spotLightMap[R]=y.map,R++,H.updateMatrices(y),y.castShadow&&W++),i.spotLightMatrix[v]=H.matrix,y.castShadow){let $=t.get(y);$.shadowIntensity=H.intensity,$.shadowBias=H.bias,$.shadowNormalBias=H.normalBias,$.shadowRadius=H.radius,$.shadowMapSize=H.mapSize,i.spotShadow[v]=$,i.spotShadowMap[v]=z,_++}v++}else if(y.isRectAreaLight){let B=e.get(y);B.color.copy(U).multiplyScalar(D),B.halfWidth.set(y.width*.5,0,0),B.halfHeight.set(0,y.height*.5,0),i.rectArea[C]=B,C++}else if(y.isPointLight){let B=e.get(y);if(B.color.copy(y.color).multiplyScalar(y.intensity),B.distance=y.distance,B.decay=y.decay,y.castShadow){let H=y.shadow,$=t.get(y);$.shadowIntensity=H.intensity,$.shadowBias=H.bias,$.shadowNormalBias=H.normalBias,$.shadowRadius=H.radius,$.shadowMapSize=H.mapSize,$.shadowCameraNear=H.camera.near,$.shadowCameraFar=H.camera.far,i.pointShadow[m]=$,i.pointShadowMap[m]=z,i.pointShadowMatrix[m]=y.shadow.matrix,T++}i.point[m]=B,m++}else if(y.isHemisphereLight){let B=e.get(y);B.skyColor.copy(y.color).multiplyScalar(D),B.groundColor.copy(y.groundColor).multiplyScalar(D),i.hemi[S]=B,S++}}C>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=Oe.LTC_FLOAT_1,i.rectAreaLTC2=Oe.LTC_FLOAT_2):(i.rectAreaLTC1=Oe.LTC_HALF_1,i.rectAreaLTC2=Oe.LTC_HALF_2)),i.ambient[0]=h,i.ambient[1]=f,i.ambient[2]=u;let L=i.hash;(L.sunLength!==p||L.directionalLength!==d||L.pointLength!==m||L.spotLength!==v||L.rectAreaLength!==C||L.hemiLength!==S||L.numSunShadows!==g||L.numDirectionalShadows!==P||L.numPointShadows!==T||L.numSpotShadows!==_||L.numSpotMaps!==R||L.numLightProbes!==O)&&(i.sun.length=p,i.directional.length=d,i.spot.length=v,i.rectArea.length=C,i.point.length=m,i.hemi.length=S,i.sunShadow.length=g,i.sunShadowMap.length=g,i.sunShadowMatrix.length=b,i.sunShadowCascade.length=b,i.directionalShadow.length=P,i.directionalShadowMap.length=P,i.directionalShadowMatrix.length=P,i.pointShadow.length=T,i.pointShadowMap.length=T,i.pointShadowMatrix.length=T,i.spotShadow.length=_,i.spotShadowMap.length=_,i.spotLightMatrix.length=_+R-W,i.spotLightMap.length=R,i.numSpotLightShadowsWithMaps=W,i.numLightProbes=O,L.sunLength=p,L.directionalLength=d,L.pointLength=m,L.spotLength=v,L.rectAreaLength=C,L.hemiLength=S,L.numSunShadows=g,L.numDirectionalShadows=P,L.numPointShadows=T,L.numSpotShadows=_,L.numSpotMaps=R,L.numLightProbes=O,i.version=eE++)}function c(l,h){let f=0,u=0,p=0,g=0,b=0,d=0,m=h.matrixWorldInverse;for(let v=0,C=l.length;v<C;v++){let S=l[v];if(S.isSunLight){let P=i.sun[f];P.direction.setFromMatrixPosition(S.matrixWorld),P.direction.transformDirection(m),f++}else if(S.isDirectionalLight){let P=i.directional[u];P.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),P.direction.sub(s),P.direction.transformDirection(m),u++}else if(S.isSpotLight){let P=i.spot[g];P.position.setFromMatrixPosition(S.matrixWorld),P.position.applyMatrix4(m),P.direction.setFromMatrixPosition(S.matrixWorld),s.setFromMatrixPosition(S.target.matrixWorld),P.direction.sub(s),P.direction.transformDirection(m),g++}else if(S.isRectAreaLight){let P=i.rectArea[b];P.position.setFromMatrixPosition(S.matrixWorld),P.position.applyMatrix4(m),o.identity(),r.copy(S.matrixWorld),r.premultiply(m),o.extractRotation(r),P.halfWidth.set(S.width*.5,0,0),P.halfHeight.set(0,S.height*.5,0),P.halfWidth.applyMatrix4(o),P.halfHeight.applyMatrix4(o),b++}else if(S.isPointLight){let P=i.point[p];P.position.setFromMatrixPosition(S.matrixWorld),P.position.applyMatrix4(m),p++}else if(S.isHemisphereLight){let P=i.hemi[d];P.direction.setFromMatrixPosition(S.matrixWorld),P.direction.transformDirection(m),d++}}}return{setup:a,setupView:c,state:i}}function P0(n){let e=new nE(n),t=[],i=[],s=[];function r(f){h.camera=f,t.length=0,i.length=0,s.length=0}function o(f){f.isLightProbeGrid?s.push(f):t.push(f)}function a(f){i.push(f)}function c(){e.setup(t),s.sort((f,u)=>f.priority-u.priority||f.id-u.id)}function l(f){e.setupView(t,f)}let h={lightsArray:t,shadowsArray:i,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:c,setupLightsView:l,pushLight:o,pushShadow:a}}function iE(n){let e=new WeakMap;function t(s,r=0){let o=e.get(s),a;return o===void 0?(a=new P0(n),e.set(s,[a])):r>=o.length?(a=new P0(n),o.push(a)):a=o[r],a}function i(){e=new WeakMap}return{get:t,dispose:i}}var sE=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,rE=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,oE=[new ee(1,0,0),new ee(-1,0,0),new ee(0,1,0),new ee(0,-1,0),new ee(0,0,1),new ee(0,0,-1)],aE=[new ee(0,-1,0),new ee(0,-1,0),new ee(0,0,1),new ee(0,0,-1),new ee(0,-1,0),new ee(0,-1,0)],I0=new nn,Ya=new ee,pd=new ee;function lE(n,e,t){let i=new Ar,s=new ft,r=new ft,o=new rn,a=new Cc,c=new Pc,l={},h=t.maxTextureSize,f={[ar]:ei,[ei]:ar,[hs]:hs},u=new cs({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new ft},radius:{value:4}},vertexShader:sE,fragmentShader:rE}),p=u.clone();p.defines.HORIZONTAL_PASS=1;let g=new ii;g.setAttribute("position",new yi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let b=new ls(g,u),d=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=ka;let m=this.type;this.render=function(T,_,R){if(d.enabled===!1||d.autoUpdate===!1&&d.needsUpdate===!1||T.length===0)return;this.type===wg&&(et("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=ka);let W=n.getRenderTarget(),O=n.getActiveCubeFace(),L=n.getActiveMipmapLevel(),G=n.state;G.setBlending(Rr),G.buffers.depth.getReversed()===!0?G.buffers.color.setClear(0,0,0,0):G.buffers.color.setClear(1,1,1,1),G.buffers.depth.setTest(!0),G.setScissorTest(!1);let X=m!==this.type;X&&_.traverse(function(y){y.material&&(Array.isArray(y.material)?y.material.forEach(U=>U.needsUpdate=!0):y.material.needsUpdate=!0)});for(let y=0,U=T.length;y<U;y++){let D=T[y],A=D.shadow;if(A===void 0){et("WebGLShadowMap:",D,"has no shadow.");continue}if(A.autoUpdate===!1&&A.needsUpdate===!1)continue;s.copy(A.mapSize);let z=A.getFrameExtents();s.multiply(z),r.copy(A.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/z.x),s.x=r.x*z.x,A.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/z.y),s.y=r.y*z.y,A.mapSize.y=r.y));let B=n.state.buffers.depth.getReversed();if(A.camera._reversedDepth=B,A.map===null||X===!0){if(A.map!==null&&(A.map.depthTexture!==null&&(A.map.depthTexture.dispose(),A.map.depthTexture=null),A.map.dispose()),this.type===Do){if(D.isPointLight){et("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}A.map=new Si(s.x,s.y,{format:lr,type:qi,minFilter:Qn,magFilter:Qn,generateMipmaps:!1}),A.map.texture.name=D.name+".shadowMap",A.map.depthTexture=new Ls(s.x,s.y,Xi),A.map.depthTexture.name=D.name+".shadowMapDepth",A.map.depthTexture.format=Ps,A.map.depthTexture.compareFunction=null,A.map.depthTexture.minFilter=Bn,A.map.depthTexture.magFilter=Bn}else D.isPointLight?(A.map=new Za(s.x),A.map.depthTexture=new Ia(s.x,Wi)):(A.map=new Si(s.x,s.y),A.map.depthTexture=new Ls(s.x,s.y,Wi)),A.map.depthTexture.name=D.name+".shadowMap",A.map.depthTexture.format=Ps,this.type===ka?(A.map.depthTexture.compareFunction=B?Jf:Zf,A.map.depthTexture.minFilter=Qn,A.map.depthTexture.magFilter=Qn):(A.map.depthTexture.compareFunction=null,A.map.depthTexture.minFilter=Bn,A.map.depthTexture.magFilter=Bn);A.camera.updateProjectionMatrix()}A.map.isWebGLCubeRenderTarget!==!0&&(A.map.width!==s.x||A.map.height!==s.y)&&A.map.setSize(s.x,s.y);let H=A.map.isWebGLCubeRenderTarget?6:A.getViewportCount();D.isPointLight!==!0&&A.updateMatrices(D,R);let $=(A.camera.layers.mask&4294967294)!==0?A.camera.layers:R.layers;for(let ne=0;ne<H;ne++){let oe=A.getCamera(ne);if(D.isPointLight){let se=A.camera,_e=A.matrix,me=D.distance||se.far;me!==se.far&&(se.far=me,se.updateProjectionMatrix()),Ya.setFromMatrixPosition(D.matrixWorld),se.position.copy(Ya),pd.copy(se.position),pd.add(oE[ne]),se.up.copy(aE[ne]),se.lookAt(pd),se.updateMatrixWorld(),_e.makeTranslation(-Ya.x,-Ya.y,-Ya.z),I0.multiplyMatrices(se.projectionMatrix,se.matrixWorldInverse),A._frustum.setFromProjectionMatrix(I0,se.coordinateSystem,se.reversedDepth)}if(A.map.isWebGLCubeRenderTarget)n.setRenderTarget(A.map,ne),n.clear();else{ne===0&&(n.setRenderTarget(A.map),n.clear());let se=A.getViewport(ne);o.set(r.x*se.x,r.y*se.y,r.x*se.z,r.y*se.w),G.viewport(o)}i=A.getFrustum(ne),S(_,R,oe,D,$,this.type)}A.isPointLightShadow!==!0&&this.type===Do&&v(A,R),A.needsUpdate=!1}m=this.type,d.needsUpdate=!1,n.setRenderTarget(W,O,L)};function v(T,_){let R=e.update(b);u.defines.VSM_SAMPLES!==T.blurSamples&&(u.defines.VSM_SAMPLES=T.blurSamples,p.defines.VSM_SAMPLES=T.blurSamples,u.needsUpdate=!0,p.needsUpdate=!0),T.mapPass===null?T.mapPass=new Si(s.x,s.y,{format:lr,type:qi}):(T.mapPass.width!==T.map.width||T.mapPass.height!==T.map.height)&&T.mapPass.setSize(T.map.width,T.map.height),u.uniforms.shadow_pass.value=T.map.depthTexture,u.uniforms.resolution.value.set(T.map.width,T.map.height),u.uniforms.radius.value=T.radius,n.setRenderTarget(T.mapPass),n.clear(),n.renderBufferDirect(_,null,R,u,b,null),p.uniforms.shadow_pass.value=T.mapPass.texture,p.uniforms.resolution.value.set(T.map.width,T.map.height),p.uniforms.radius.value=T.radius,n.setRenderTarget(T.map),n.clear(),n.renderBufferDirect(_,null,R,p,b,null)}function C(T,_,R,W){let O=null,L=R.isPointLight===!0?T.customDistanceMaterial:T.customDepthMaterial;if(L!==void 0)O=L;else if(O=R.isPointLight===!0?c:a,n.localClippingEnabled&&_.clipShadows===!0&&Array.isArray(_.clippingPlanes)&&_.clippingPlanes.length!==0||_.displacementMap&&_.displacementScale!==0||_.alphaMap&&_.alphaTest>0||_.map&&_.alphaTest>0||_.alphaToCoverage===!0){let G=O.uuid,X=_.uuid,y=l[G];y===void 0&&(y={},l[G]=y);let U=y[X];U===void 0&&(U=O.clone(),y[X]=U,_.addEventListener("dispose",P)),O=U}if(O.visible=_.visible,O.wireframe=_.wireframe,W===Do?O.side=_.shadowSide!==null?_.shadowSide:_.side:O.side=_.shadowSide!==null?_.shadowSide:f[_.side],O.alphaMap=_.alphaMap,O.alphaTest=_.alphaToCoverage===!0?.5:_.alphaTest,O.map=_.map,O.clipShadows=_.clipShadows,O.clippingPlanes=_.clippingPlanes,O.clipIntersection=_.clipIntersection,O.displacementMap=_.displacementMap,O.displacementScale=_.displacementScale,O.displacementBias=_.displacementBias,O.wireframeLinewidth=_.wireframeLinewidth,O.linewidth=_.linewidth,R.isPointLight===!0&&O.isMeshDistanceMaterial===!0){let G=n.properties.get(O);G.light=R}return O}function S(T,_,R,W,O,L){if(T.visible===!1)return;if(T.layers.test(O)&&(T.isMesh||T.isLine||T.isPoints)&&(T.castShadow||T.receiveShadow&&L===Do)&&(!T.frustumCulled||T.intersectsFrustum(i))){T.modelViewMatrix.multiplyMatrices(R.matrixWorldInverse,T.matrixWorld);let y=e.update(T),U=T.material;if(Array.isArray(U)){let D=y.groups;for(let A=0,z=D.length;A<z;A++){let B=D[A],H=U[B.materialIndex];if(H&&H.visible){let $=C(T,H,W,L);T.onBeforeShadow(n,T,_,R,y,$,B),n.renderBufferDirect(R,null,y,$,T,B),T.onAfterShadow(n,T,_,R,y,$,B)}}}else if(U.visible){let D=C(T,U,W,L);T.onBeforeShadow(n,T,_,R,y,D,null),n.renderBufferDirect(R,null,y,D,T,null),T.onAfterShadow(n,T,_,R,y,D,null)}}let X=T.children;for(let y=0,U=X.length;y<U;y++)S(X[y],_,R,W,O,L)}function P(T){T.target.removeEventListener("dispose",P);for(let R in l){let W=l[R],O=T.target.uuid;O in W&&(W[O].dispose(),delete W[O])}}}function cE(n,e){function t(){let V=!1,he=new rn,le=null,Re=new rn(0,0,0,0);return{setMask:function(ve){le!==ve&&!V&&(n.colorMask(ve,ve,ve,ve),le=ve)},setLocked:function(ve){V=ve},setClear:function(ve,Te,Je,it,de){de===!0&&(ve*=it,Te*=it,Je*=it),he.set(ve,Te,Je,it),Re.equals(he)===!1&&(n.clearColor(ve,Te,Je,it),Re.copy(he))},reset:function(){V=!1,le=null,Re.set(-1,0,0,0)}}}function i(){let V=!1,he=!1,le=null,Re=null,ve=null;return{setReversed:function(Te){if(he!==Te){let Je=e.get("EXT_clip_control");Te?Je.clipControlEXT(Je.LOWER_LEFT_EXT,Je.ZERO_TO_ONE_EXT):Je.clipControlEXT(Je.LOWER_LEFT_EXT,Je.NEGATIVE_ONE_TO_ONE_EXT),he=Te;let it=ve;ve=null,this.setClear(it)}},getReversed:function(){return he},setTest:function(Te){Te?Se(n.DEPTH_TEST):Ze(n.DEPTH_TEST)},setMask:function(Te){le!==Te&&!V&&(n.depthMask(Te),le=Te)},setFunc:function(Te){if(he&&(Te=s0[Te]),Re!==Te){switch(Te){case cc:n.depthFunc(n.NEVER);break;case hc:n.depthFunc(n.ALWAYS);break;case uc:n.depthFunc(n.LESS);break;case bo:n.depthFunc(n.LEQUAL);break;case fc:n.depthFunc(n.EQUAL);break;case dc:n.depthFunc(n.GEQUAL);break;case pc:n.depthFunc(n.GREATER);break;case mc:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Re=Te}},setLocked:function(Te){V=Te},setClear:function(Te){ve!==Te&&(ve=Te,he&&(Te=1-Te),n.clearDepth(Te))},reset:function(){V=!1,le=null,Re=null,ve=null,he=!1}}}function s(){let V=!1,he=null,le=null,Re=null,ve=null,Te=null,Je=null,it=null,de=null;return{setTest:function(We){V||(We?Se(n.STENCIL_TEST):Ze(n.STENCIL_TEST))},setMask:function(We){he!==We&&!V&&(n.stencilMask(We),he=We)},setFunc:function(We,st,Le){(le!==We||Re!==st||ve!==Le)&&(n.stencilFunc(We,st,Le),le=We,Re=st,ve=Le)},setOp:function(We,st,Le){(Te!==We||Je!==st||it!==Le)&&(n.stencilOp(We,st,Le),Te=We,Je=st,it=Le)},setLocked:function(We){V=We},setClear:function(We){de!==We&&(n.clearStencil(We),de=We)},reset:function(){V=!1,he=null,le=null,Re=null,ve=null,Te=null,Je=null,it=null,de=null}}}let r=new t,o=new i,a=new s,c={},l=new WeakMap,h={},f={},u={},p=new WeakMap,g=[],b=null,d=!1,m=null,v=null,C=null,S=null,P=null,T=null,_=null,R=new _t(0,0,0),W=0,O=!1,L=null,G=null,X=null,y=null,U=null,D=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS),A=!1,z=0,B=n.getParameter(n.VERSION);B.indexOf("WebGL")!==-1?(z=parseFloat(/^WebGL (\d)/.exec(B)[1]),A=z>=1):B.indexOf("OpenGL ES")!==-1&&(z=parseFloat(/^OpenGL ES (\d)/.exec(B)[1]),A=z>=2);let H=null,$={},ne=n.getParameter(n.SCISSOR_BOX),oe=n.getParameter(n.VIEWPORT),se=new rn().fromArray(ne),_e=new rn().fromArray(oe);function me(V,he,le,Re){let ve=new Uint8Array(4),Te=n.createTexture();n.bindTexture(V,Te),n.texParameteri(V,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(V,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let Je=0;Je<le;Je++)V===n.TEXTURE_3D||V===n.TEXTURE_2D_ARRAY?n.texImage3D(he,0,n.RGBA,1,1,Re,0,n.RGBA,n.UNSIGNED_BYTE,ve):n.texImage2D(he+Je,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,ve);return Te}let Ee={};Ee[n.TEXTURE_2D]=me(n.TEXTURE_2D,n.TEXTURE_2D,1),Ee[n.TEXTURE_CUBE_MAP]=me(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),Ee[n.TEXTURE_2D_ARRAY]=me(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),Ee[n.TEXTURE_3D]=me(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),o.setClear(1),a.setClear(0),Se(n.DEPTH_TEST),o.setFunc(bo),zt(!1),ct(Tf),Se(n.CULL_FACE),yt(Rr);function Se(V){h[V]!==!0&&(n.enable(V),h[V]=!0)}function Ze(V){h[V]!==!1&&(n.disable(V),h[V]=!1)}function rt(V,he){return u[V]!==he?(n.bindFramebuffer(V,he),u[V]=he,V===n.DRAW_FRAMEBUFFER&&(u[n.FRAMEBUFFER]=he),V===n.FRAMEBUFFER&&(u[n.DRAW_FRAMEBUFFER]=he),!0):!1}function Ye(V,he){let le=g,Re=!1;if(V){le=p.get(he),le===void 0&&(le=[],p.set(he,le));let ve=V.textures;if(le.length!==ve.length||le[0]!==n.COLOR_ATTACHMENT0){for(let Te=0,Je=ve.length;Te<Je;Te++)le[Te]=n.COLOR_ATTACHMENT0+Te;le.length=ve.length,Re=!0}}else le[0]!==n.BACK&&(le[0]=n.BACK,Re=!0);Re&&n.drawBuffers(le)}function Ie(V){return b!==V?(n.useProgram(V),b=V,!0):!1}let Ue={[Cr]:n.FUNC_ADD,[Tg]:n.FUNC_SUBTRACT,[Ag]:n.FUNC_REVERSE_SUBTRACT};Ue[Rg]=n.MIN,Ue[Cg]=n.MAX;let Ve={[Pg]:n.ZERO,[Ig]:n.ONE,[Lg]:n.SRC_COLOR,[Pf]:n.SRC_ALPHA,[Bg]:n.SRC_ALPHA_SATURATE,[Fg]:n.DST_COLOR,[Ng]:n.DST_ALPHA,[Dg]:n.ONE_MINUS_SRC_COLOR,[If]:n.ONE_MINUS_SRC_ALPHA,[Og]:n.ONE_MINUS_DST_COLOR,[Ug]:n.ONE_MINUS_DST_ALPHA,[kg]:n.CONSTANT_COLOR,[zg]:n.ONE_MINUS_CONSTANT_COLOR,[Vg]:n.CONSTANT_ALPHA,[Hg]:n.ONE_MINUS_CONSTANT_ALPHA};function yt(V,he,le,Re,ve,Te,Je,it,de,We){if(V===Rr){d===!0&&(Ze(n.BLEND),d=!1);return}if(d===!1&&(Se(n.BLEND),d=!0),V!==Eg){if(V!==m||We!==O){if((v!==Cr||P!==Cr)&&(n.blendEquation(n.FUNC_ADD),v=Cr,P=Cr),We)switch(V){case No:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Af:n.blendFunc(n.ONE,n.ONE);break;case Rf:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case Cf:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:at("WebGLState: Invalid blending: ",V);break}else switch(V){case No:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case Af:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case Rf:at("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Cf:at("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:at("WebGLState: Invalid blending: ",V);break}C=null,S=null,T=null,_=null,R.set(0,0,0),W=0,m=V,O=We}return}ve=ve||he,Te=Te||le,Je=Je||Re,(he!==v||ve!==P)&&(n.blendEquationSeparate(Ue[he],Ue[ve]),v=he,P=ve),(le!==C||Re!==S||Te!==T||Je!==_)&&(n.blendFuncSeparate(Ve[le],Ve[Re],Ve[Te],Ve[Je]),C=le,S=Re,T=Te,_=Je),(it.equals(R)===!1||de!==W)&&(n.blendColor(it.r,it.g,it.b,de),R.copy(it),W=de),m=V,O=!1}function Pt(V,he){V.side===hs?Ze(n.CULL_FACE):Se(n.CULL_FACE);let le=V.side===ei;he&&(le=!le),zt(le),V.blending===No&&V.transparent===!1?yt(Rr):yt(V.blending,V.blendEquation,V.blendSrc,V.blendDst,V.blendEquationAlpha,V.blendSrcAlpha,V.blendDstAlpha,V.blendColor,V.blendAlpha,V.premultipliedAlpha),o.setFunc(V.depthFunc),o.setTest(V.depthTest),o.setMask(V.depthWrite),r.setMask(V.colorWrite);let Re=V.stencilWrite;a.setTest(Re),Re&&(a.setMask(V.stencilWriteMask),a.setFunc(V.stencilFunc,V.stencilRef,V.stencilFuncMask),a.setOp(V.stencilFail,V.stencilZFail,V.stencilZPass)),je(V.polygonOffset,V.polygonOffsetFactor,V.polygonOffsetUnits),V.alphaToCoverage===!0?Se(n.SAMPLE_ALPHA_TO_COVERAGE):Ze(n.SAMPLE_ALPHA_TO_COVERAGE)}function zt(V){L!==V&&(V?n.frontFace(n.CW):n.frontFace(n.CCW),L=V)}function ct(V){V!==Mg?(Se(n.CULL_FACE),V!==G&&(V===Tf?n.cullFace(n.BACK):V===bg?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):Ze(n.CULL_FACE),G=V}function It(V){V!==X&&(A&&n.lineWidth(V),X=V)}function je(V,he,le){V?(Se(n.POLYGON_OFFSET_FILL),(y!==he||U!==le)&&(y=he,U=le,o.getReversed()&&(he=-he,le=-le),n.polygonOffset(he,le))):Ze(n.POLYGON_OFFSET_FILL)}function dt(V){V?Se(n.SCISSOR_TEST):Ze(n.SCISSOR_TEST)}function mt(V){V===void 0&&(V=n.TEXTURE0+D-1),H!==V&&(n.activeTexture(V),H=V)}function bt(V,he,le){le===void 0&&(H===null?le=n.TEXTURE0+D-1:le=H);let Re=$[le];Re===void 0&&(Re={type:void 0,texture:void 0},$[le]=Re),(Re.type!==V||Re.texture!==he)&&(H!==le&&(n.activeTexture(le),H=le),n.bindTexture(V,he||Ee[V]),Re.type=V,Re.texture=he)}function k(){let V=$[H];V!==void 0&&V.type!==void 0&&(n.bindTexture(V.type,null),V.type=void 0,V.texture=void 0)}function De(){try{n.compressedTexImage2D(...arguments)}catch(V){at("WebGLState:",V)}}function tt(){try{n.compressedTexImage3D(...arguments)}catch(V){at("WebGLState:",V)}}function ut(){try{n.texSubImage2D(...arguments)}catch(V){at("WebGLState:",V)}}function Ae(){try{n.texSubImage3D(...arguments)}catch(V){at("WebGLState:",V)}}function Xt(){try{n.compressedTexSubImage2D(...arguments)}catch(V){at("WebGLState:",V)}}function $e(){try{n.compressedTexSubImage3D(...arguments)}catch(V){at("WebGLState:",V)}}function Qe(){try{n.texStorage2D(...arguments)}catch(V){at("WebGLState:",V)}}function I(){try{n.texStorage3D(...arguments)}catch(V){at("WebGLState:",V)}}function M(){try{n.texImage2D(...arguments)}catch(V){at("WebGLState:",V)}}function J(){try{n.texImage3D(...arguments)}catch(V){at("WebGLState:",V)}}function pe(V){return f[V]!==void 0?f[V]:n.getParameter(V)}function ue(V,he){f[V]!==he&&(n.pixelStorei(V,he),f[V]=he)}function Me(V){se.equals(V)===!1&&(n.scissor(V.x,V.y,V.z,V.w),se.copy(V))}function be(V){_e.equals(V)===!1&&(n.viewport(V.x,V.y,V.z,V.w),_e.copy(V))}function ae(V,he){let le=l.get(he);le===void 0&&(le=new WeakMap,l.set(he,le));let Re=le.get(V);Re===void 0&&(Re=n.getUniformBlockIndex(he,V.name),n.uniformBlockBinding(he,Re,Re),le.set(V,Re))}function ce(V,he,le){let ve=l.get(he).get(V);c[ve]!==le&&(n.bindBufferBase(n.UNIFORM_BUFFER,ve,le),c[ve]=le)}function xe(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),o.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),h={},f={},H=null,$={},u={},c={},p=new WeakMap,g=[],b=null,d=!1,m=null,v=null,C=null,S=null,P=null,T=null,_=null,R=new _t(0,0,0),W=0,O=!1,L=null,G=null,X=null,y=null,U=null,se.set(0,0,n.canvas.width,n.canvas.height),_e.set(0,0,n.canvas.width,n.canvas.height),r.reset(),o.reset(),a.reset()}return{buffers:{color:r,depth:o,stencil:a},enable:Se,disable:Ze,bindFramebuffer:rt,drawBuffers:Ye,useProgram:Ie,setBlending:yt,setMaterial:Pt,setFlipSided:zt,setCullFace:ct,setLineWidth:It,setPolygonOffset:je,setScissorTest:dt,activeTexture:mt,bindTexture:bt,unbindTexture:k,compressedTexImage2D:De,compressedTexImage3D:tt,texImage2D:M,texImage3D:J,pixelStorei:ue,getParameter:pe,updateUBOMapping:ae,uniformBlockBinding:ce,texStorage2D:Qe,texStorage3D:I,texSubImage2D:ut,texSubImage3D:Ae,compressedTexSubImage2D:Xt,compressedTexSubImage3D:$e,scissor:Me,viewport:be,reset:xe}}function hE(n,e,t,i,s,r,o){let a=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new ft,h=new WeakMap,f=new Set,u,p=new WeakMap,g=new Set,b=new FinalizationRegistry(I=>g.delete(I)),d=!1;try{d=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function m(I,M){return d?new OffscreenCanvas(I,M):Ma("canvas")}function v(I,M,J){let pe=1,ue=Qe(I);if((ue.width>J||ue.height>J)&&(pe=J/Math.max(ue.width,ue.height)),pe<1)if(typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&I instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&I instanceof ImageBitmap||typeof VideoFrame<"u"&&I instanceof VideoFrame){let Me=Math.floor(pe*ue.width),be=Math.floor(pe*ue.height);u===void 0&&(u=m(Me,be));let ae=M?m(Me,be):u;return ae.width=Me,ae.height=be,ae.getContext("2d").drawImage(I,0,0,Me,be),et("WebGLRenderer: Texture has been resized from ("+ue.width+"x"+ue.height+") to ("+Me+"x"+be+")."),ae}else return"data"in I&&et("WebGLRenderer: Image in DataTexture is too big ("+ue.width+"x"+ue.height+")."),I;return I}function C(I){return I.generateMipmaps}function S(I){n.generateMipmap(I)}function P(I){return I.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:I.isWebGL3DRenderTarget?n.TEXTURE_3D:I.isWebGLArrayRenderTarget||I.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function T(I,M,J,pe,ue,Me=!1){if(I!==null){if(n[I]!==void 0)return n[I];et("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+I+"'")}let be;pe&&(be=e.get("EXT_texture_norm16"),be||et("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let ae=M;if(M===n.RED&&(J===n.FLOAT&&(ae=n.R32F),J===n.HALF_FLOAT&&(ae=n.R16F),J===n.UNSIGNED_BYTE&&(ae=n.R8),J===n.UNSIGNED_SHORT&&be&&(ae=be.R16_EXT),J===n.SHORT&&be&&(ae=be.R16_SNORM_EXT)),M===n.RED_INTEGER&&(J===n.UNSIGNED_BYTE&&(ae=n.R8UI),J===n.UNSIGNED_SHORT&&(ae=n.R16UI),J===n.UNSIGNED_INT&&(ae=n.R32UI),J===n.BYTE&&(ae=n.R8I),J===n.SHORT&&(ae=n.R16I),J===n.INT&&(ae=n.R32I)),M===n.RG&&(J===n.FLOAT&&(ae=n.RG32F),J===n.HALF_FLOAT&&(ae=n.RG16F),J===n.UNSIGNED_BYTE&&(ae=n.RG8),J===n.UNSIGNED_SHORT&&be&&(ae=be.RG16_EXT),J===n.SHORT&&be&&(ae=be.RG16_SNORM_EXT)),M===n.RG_INTEGER&&(J===n.UNSIGNED_BYTE&&(ae=n.RG8UI),J===n.UNSIGNED_SHORT&&(ae=n.RG16UI),J===n.UNSIGNED_INT&&(ae=n.RG32UI),J===n.BYTE&&(ae=n.RG8I),J===n.SHORT&&(ae=n.RG16I),J===n.INT&&(ae=n.RG32I)),M===n.RGB_INTEGER&&(J===n.UNSIGNED_BYTE&&(ae=n.RGB8UI),J===n.UNSIGNED_SHORT&&(ae=n.RGB16UI),J===n.UNSIGNED_INT&&(ae=n.RGB32UI),J===n.BYTE&&(ae=n.RGB8I),J===n.SHORT&&(ae=n.RGB16I),J===n.INT&&(ae=n.RGB32I)),M===n.RGBA_INTEGER&&(J===n.UNSIGNED_BYTE&&(ae=n.RGBA8UI),J===n.UNSIGNED_SHORT&&(ae=n.RGBA16UI),J===n.UNSIGNED_INT&&(ae=n.RGBA32UI),J===n.BYTE&&(ae=n.RGBA8I),J===n.SHORT&&(ae=n.RGBA16I),J===n.INT&&(ae=n.RGBA32I)),M===n.RGB&&(J===n.UNSIGNED_SHORT&&be&&(ae=be.RGB16_EXT),J===n.SHORT&&be&&(ae=be.RGB16_SNORM_EXT),J===n.UNSIGNED_INT_5_9_9_9_REV&&(ae=n.RGB9_E5),J===n.UNSIGNED_INT_10F_11F_11F_REV&&(ae=n.R11F_G11F_B10F)),M===n.RGBA){let ce=Me?va:At.getTransfer(ue);J===n.FLOAT&&(ae=n.RGBA32F),J===n.HALF_FLOAT&&(ae=n.RGBA16F),J===n.UNSIGNED_BYTE&&(ae=ce===kt?n.SRGB8_ALPHA8:n.RGBA8),J===n.UNSIGNED_SHORT&&be&&(ae=be.RGBA16_EXT),J===n.SHORT&&be&&(ae=be.RGBA16_SNORM_EXT),J===n.UNSIGNED_SHORT_4_4_4_4&&(ae=n.RGBA4),J===n.UNSIGNED_SHORT_5_5_5_1&&(ae=n.RGB5_A1)}return(ae===n.R16F||ae===n.R32F||ae===n.RG16F||ae===n.RG32F||ae===n.RGBA16F||ae===n.RGBA32F)&&e.get("EXT_color_buffer_float"),ae}function _(I,M){let J;return I?M===null||M===Wi||M===Ir?J=n.DEPTH24_STENCIL8:M===Xi?J=n.DEPTH32F_STENCIL8:M===Fo&&(J=n.DEPTH24_STENCIL8,et("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):M===null||M===Wi||M===Ir?J=n.DEPTH_COMPONENT24:M===Xi?J=n.DEPTH_COMPONENT32F:M===Fo&&(J=n.DEPTH_COMPONENT16),J}function R(I,M){return C(I)===!0||I.isFramebufferTexture&&I.minFilter!==Bn&&I.minFilter!==Qn?Math.log2(Math.max(M.width,M.height))+1:I.mipmaps.length>0?I.mipmaps.length:I.isCompressedTexture&&Array.isArray(I.image)?M.mipmaps.length:1}function W(I){let M=new WeakRef(I);i.get(I).__ref=M,g.add(M),b.register(I,M,M)}function O(I){let M=i.get(I).__ref;M!==void 0&&(g.delete(M),b.unregister(M))}function L(I){X(I.target)}function G(I){y(I.target)}function X(I){I.removeEventListener("dispose",L),O(I),D(I),I.isVideoTexture&&h.delete(I),I.isHTMLTexture&&f.delete(I)}function y(I){I.removeEventListener("dispose",G),O(I),z(I)}function U(){for(let I of g){let M=I.deref();M!==void 0&&(M.isRenderTarget===!0?y(M):X(M))}g.clear(),f.clear()}function D(I){let M=i.get(I);if(M.__webglInit===void 0)return;let J=I.source,pe=p.get(J);if(pe){let ue=pe[M.__cacheKey];ue.usedTimes--,ue.usedTimes===0&&A(I),Object.keys(pe).length===0&&p.delete(J)}i.remove(I)}function A(I){let M=i.get(I);n.deleteTexture(M.__webglTexture);let J=I.source,pe=p.get(J);delete pe[M.__cacheKey],o.memory.textures--}function z(I){let M=i.get(I);M.__depthDisposeCallback&&M.__depthDisposeCallback();let J=I.depthTexture;if(J&&J.renderTarget===I&&X(J),I.isWebGLCubeRenderTarget)for(let ue=0;ue<6;ue++){if(Array.isArray(M.__webglFramebuffer[ue]))for(let Me=0;Me<M.__webglFramebuffer[ue].length;Me++)n.deleteFramebuffer(M.__webglFramebuffer[ue][Me]);else n.deleteFramebuffer(M.__webglFramebuffer[ue]);M.__webglDepthbuffer&&n.deleteRenderbuffer(M.__webglDepthbuffer[ue])}else{if(Array.isArray(M.__webglFramebuffer))for(let ue=0;ue<M.__webglFramebuffer.length;ue++)n.deleteFramebuffer(M.__webglFramebuffer[ue]);else n.deleteFramebuffer(M.__webglFramebuffer);if(M.__webglDepthbuffer&&n.deleteRenderbuffer(M.__webglDepthbuffer),M.__webglMultisampledFramebuffer&&n.deleteFramebuffer(M.__webglMultisampledFramebuffer),M.__webglColorRenderbuffer)for(let ue=0;ue<M.__webglColorRenderbuffer.length;ue++)M.__webglColorRenderbuffer[ue]&&n.deleteRenderbuffer(M.__webglColorRenderbuffer[ue]);M.__webglDepthRenderbuffer&&n.deleteRenderbuffer(M.__webglDepthRenderbuffer)}let pe=I.textures;for(let ue=0,Me=pe.length;ue<Me;ue++){let be=i.get(pe[ue]);be.__webglTexture&&(n.deleteTexture(be.__webglTexture),o.memory.textures--),i.remove(pe[ue])}i.remove(I)}let B=0;function H(){B=0}function $(){return B}function ne(I){B=I}function oe(){let I=B;return I>=s.maxTextures&&et("WebGLTextures: Trying to use "+(I+1)+" texture units while this GPU supports only "+s.maxTextures),B+=1,I}function se(I){let M=[];return M.push(I.wrapS),M.push(I.wrapT),M.push(I.wrapR||0),M.push(I.magFilter),M.push(I.minFilter),M.push(I.anisotropy),M.push(I.internalFormat),M.push(I.format),M.push(I.type),M.push(I.generateMipmaps),M.push(I.mipmapsAutoUpdate),M.push(I.premultiplyAlpha),M.push(I.flipY),M.push(I.unpackAlignment),M.push(I.colorSpace),M.join()}function _e(I,M){let J=i.get(I);if(I.isVideoTexture&&Xt(I),I.isRenderTargetTexture===!1&&I.isExternalTexture!==!0&&I.version>0&&J.__version!==I.version){let pe=I.image;if(pe===null)et("WebGLRenderer: Texture marked for update but no image data found.");else if(pe.complete===!1)et("WebGLRenderer: Texture marked for update but image is incomplete");else{Pt(J,I,M);return}}else I.isExternalTexture&&(J.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D,J.__webglTexture,n.TEXTURE0+M)}function me(I,M){let J=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&J.__version!==I.version){Pt(J,I,M);return}else I.isExternalTexture&&(J.__webglTexture=I.sourceTexture?I.sourceTexture:null);t.bindTexture(n.TEXTURE_2D_ARRAY,J.__webglTexture,n.TEXTURE0+M)}function Ee(I,M){let J=i.get(I);if(I.isRenderTargetTexture===!1&&I.version>0&&J.__version!==I.version){Pt(J,I,M);return}t.bindTexture(n.TEXTURE_3D,J.__webglTexture,n.TEXTURE0+M)}function Se(I,M){let J=i.get(I);if(I.version>0&&J.__version!==I.version){zt(J,I,M);return}t.bindTexture(n.TEXTURE_CUBE_MAP,J.__webglTexture,n.TEXTURE0+M)}let Ze={[gc]:n.REPEAT,[as]:n.CLAMP_TO_EDGE,[_c]:n.MIRRORED_REPEAT},rt={[Bn]:n.NEAREST,[Xg]:n.NEAREST_MIPMAP_NEAREST,[za]:n.NEAREST_MIPMAP_LINEAR,[Qn]:n.LINEAR,[qc]:n.LINEAR_MIPMAP_NEAREST,[Ds]:n.LINEAR_MIPMAP_LINEAR},Ye={[Zg]:n.NEVER,[Kf]:n.ALWAYS,[Jg]:n.LESS,[Zf]:n.LEQUAL,[Kg]:n.EQUAL,[Jf]:n.GEQUAL,[jg]:n.GREATER,[Qg]:n.NOTEQUAL};function Ie(I,M){if(M.type===Xi&&e.has("OES_texture_float_linear")===!1&&(M.magFilter===Qn||M.magFilter===qc||M.magFilter===za||M.magFilter===Ds||M.minFilter===Qn||M.minFilter===qc||M.minFilter===za||M.minFilter===Ds)&&et("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(I,n.TEXTURE_WRAP_S,Ze[M.wrapS]),n.texParameteri(I,n.TEXTURE_WRAP_T,Ze[M.wrapT]),(I===n.TEXTURE_3D||I===n.TEXTURE_2D_ARRAY)&&n.texParameteri(I,n.TEXTURE_WRAP_R,Ze[M.wrapR]),n.texParameteri(I,n.TEXTURE_MAG_FILTER,rt[M.magFilter]),n.texParameteri(I,n.TEXTURE_MIN_FILTER,rt[M.minFilter]),M.compareFunction&&(n.texParameteri(I,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(I,n.TEXTURE_COMPARE_FUNC,Ye[M.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(M.magFilter===Bn||M.minFilter!==za&&M.minFilter!==Ds||M.type===Xi&&e.has("OES_texture_float_linear")===!1)return;if(M.anisotropy>1||i.get(M).__currentAnisotropy){let J=e.get("EXT_texture_filter_anisotropic");n.texParameterf(I,J.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(M.anisotropy,s.getMaxAnisotropy())),i.get(M).__currentAnisotropy=M.anisotropy}}}function Ue(I,M){let J=!1;I.__webglInit===void 0&&(I.__webglInit=!0,M.addEventListener("dispose",L),W(M));let pe=M.source,ue=p.get(pe);ue===void 0&&(ue={},p.set(pe,ue));let Me=se(M);if(Me!==I.__cacheKey){ue[Me]===void 0&&(ue[Me]={texture:n.createTexture(),usedTimes:0},o.memory.textures++,J=!0),ue[Me].usedTimes++;let be=ue[I.__cacheKey];be!==void 0&&(ue[I.__cacheKey].usedTimes--,be.usedTimes===0&&A(M)),I.__cacheKey=Me,I.__webglTexture=ue[Me].texture}return J}function Ve(I,M,J){return Math.floor(Math.floor(I/J)/M)}function yt(I,M,J,pe){let Me=I.updateRanges;if(Me.length===0)t.texSubImage2D(n.TEXTURE_2D,0,0,0,M.width,M.height,J,pe,M.data);else{Me.sort((V,he)=>V.start-he.start);let be=0;for(let V=1;V<Me.length;V++){let he=Me[be],le=Me[V],Re=he.start+he.count,ve=Ve(le.start,M.width,4),Te=Ve(he.start,M.width,4);le.start<=Re+1&&ve===Te&&Ve(le.start+le.count-1,M.width,4)===ve?he.count=Math.max(he.count,le.start+le.count-he.start):(++be,Me[be]=le)}Me.length=be+1;let ae=t.getParameter(n.UNPACK_ROW_LENGTH),ce=t.getParameter(n.UNPACK_SKIP_PIXELS),xe=t.getParameter(n.UNPACK_SKIP_ROWS);t.pixelStorei(n.UNPACK_ROW_LENGTH,M.width);for(let V=0,he=Me.length;V<he;V++){let le=Me[V],Re=Math.floor(le.start/4),ve=Math.ceil(le.count/4),Te=Re%M.width,Je=Math.floor(Re/M.width),it=ve,de=1;t.pixelStorei(n.UNPACK_SKIP_PIXELS,Te),t.pixelStorei(n.UNPACK_SKIP_ROWS,Je),t.texSubImage2D(n.TEXTURE_2D,0,Te,Je,it,de,J,pe,M.data)}I.clearUpdateRanges(),t.pixelStorei(n.UNPACK_ROW_LENGTH,ae),t.pixelStorei(n.UNPACK_SKIP_PIXELS,ce),t.pixelStorei(n.UNPACK_SKIP_ROWS,xe)}}function Pt(I,M,J){let pe=n.TEXTURE_2D;(M.isDataArrayTexture||M.isCompressedArrayTexture)&&(pe=n.TEXTURE_2D_ARRAY),M.isData3DTexture&&(pe=n.TEXTURE_3D);let ue=Ue(I,M),Me=M.source;t.bindTexture(pe,I.__webglTexture,n.TEXTURE0+J);let be=i.get(Me);if(Me.version!==be.__version||ue===!0){if(t.activeTexture(n.TEXTURE0+J),(typeof ImageBitmap<"u"&&M.image instanceof ImageBitmap)===!1){let de=At.getPrimaries(At.workingColorSpace),We=M.colorSpace===Us?null:At.getPrimaries(M.colorSpace),st=M.colorSpace===Us||de===We?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,M.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,M.premultiplyAlpha),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,st)}t.pixelStorei(n.UNPACK_ALIGNMENT,M.unpackAlignment);let ce=v(M.image,!1,s.maxTextureSize);ce=$e(M,ce);let xe=r.convert(M.format,M.colorSpace),V=r.convert(M.type),he=T(M.internalFormat,xe,V,M.normalized,M.colorSpace,M.isVideoTexture);Ie(pe,M);let le,Re=M.mipmaps,ve=M.isVideoTexture!==!0,Te=be.__version===void 0||ue===!0,Je=Me.dataReady,it=R(M,ce);if(M.isDepthTexture)he=_(M.format===Ns,M.type),Te&&(ve?t.texStorage2D(n.TEXTURE_2D,1,he,ce.width,ce.height):t.texImage2D(n.TEXTURE_2D,0,he,ce.width,ce.height,0,xe,V,null));else if(M.isDataTexture)if(Re.length>0){ve&&Te&&t.texStorage2D(n.TEXTURE_2D,it,he,Re[0].width,Re[0].height);for(let de=0,We=Re.length;de<We;de++)le=Re[de],ve?Je&&t.texSubImage2D(n.TEXTURE_2D,de,0,0,le.width,le.height,xe,V,le.data):t.texImage2D(n.TEXTURE_2D,de,he,le.width,le.height,0,xe,V,le.data);M.generateMipmaps=!1}else ve?(Te&&t.texStorage2D(n.TEXTURE_2D,it,he,ce.width,ce.height),Je&&yt(M,ce,xe,V)):t.texImage2D(n.TEXTURE_2D,0,he,ce.width,ce.height,0,xe,V,ce.data);else if(M.isCompressedTexture)if(M.isCompressedArrayTexture){ve&&Te&&t.texStorage3D(n.TEXTURE_2D_ARRAY,it,he,Re[0].width,Re[0].height,ce.depth);for(let de=0,We=Re.length;de<We;de++)if(le=Re[de],M.format!==Yi)if(xe!==null)if(ve){if(Je)if(M.layerUpdates.size>0){let st=ad(le.width,le.height,M.format,M.type);for(let Le of M.layerUpdates){let pt=le.data.subarray(Le*st/le.data.BYTES_PER_ELEMENT,(Le+1)*st/le.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,de,0,0,Le,le.width,le.height,1,xe,pt)}}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,de,0,0,0,le.width,le.height,ce.depth,xe,le.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,de,he,le.width,le.height,ce.depth,0,le.data,0,0);else et("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else ve?Je&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,de,0,0,0,le.width,le.height,ce.depth,xe,V,le.data):t.texImage3D(n.TEXTURE_2D_ARRAY,de,he,le.width,le.height,ce.depth,0,xe,V,le.data);M.layerUpdates.size>0&&M.clearLayerUpdates()}else{ve&&Te&&t.texStorage2D(n.TEXTURE_2D,it,he,Re[0].width,Re[0].height);for(let de=0,We=Re.length;de<We;de++)le=Re[de],M.format!==Yi?xe!==null?ve?Je&&t.compressedTexSubImage2D(n.TEXTURE_2D,de,0,0,le.width,le.height,xe,le.data):t.compressedTexImage2D(n.TEXTURE_2D,de,he,le.width,le.height,0,le.data):et("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):ve?Je&&t.texSubImage2D(n.TEXTURE_2D,de,0,0,le.width,le.height,xe,V,le.data):t.texImage2D(n.TEXTURE_2D,de,he,le.width,le.height,0,xe,V,le.data)}else if(M.isDataArrayTexture)if(ve){if(Te&&t.texStorage3D(n.TEXTURE_2D_ARRAY,it,he,ce.width,ce.height,ce.depth),Je)if(M.layerUpdates.size>0){let de=ad(ce.width,ce.height,M.format,M.type);for(let We of M.layerUpdates){let st=ce.data.subarray(We*de/ce.data.BYTES_PER_ELEMENT,(We+1)*de/ce.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,We,ce.width,ce.height,1,xe,V,st)}M.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,ce.width,ce.height,ce.depth,xe,V,ce.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,he,ce.width,ce.height,ce.depth,0,xe,V,ce.data);else if(M.isData3DTexture)ve?(Te&&t.texStorage3D(n.TEXTURE_3D,it,he,ce.width,ce.height,ce.depth),Je&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,ce.width,ce.height,ce.depth,xe,V,ce.data)):t.texImage3D(n.TEXTURE_3D,0,he,ce.width,ce.height,ce.depth,0,xe,V,ce.data);else if(M.isFramebufferTexture){if(Te)if(ve)t.texStorage2D(n.TEXTURE_2D,it,he,ce.width,ce.height);else{let de=ce.width,We=ce.height;for(let st=0;st<it;st++)t.texImage2D(n.TEXTURE_2D,st,he,de,We,0,xe,V,null),de>>=1,We>>=1}}else if(M.isHTMLTexture){if("texElementImage2D"in n){let de=n.canvas;if(de.hasAttribute("layoutsubtree")||de.setAttribute("layoutsubtree","true"),ce.parentNode!==de){de.appendChild(ce),f.add(M),de.onpaint=We=>{let st=We.changedElements;for(let Le of f)st.includes(Le.image)&&(Le.needsUpdate=!0)},de.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,ce);else{let st=n.RGBA,Le=n.RGBA,pt=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,st,Le,pt,ce)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Re.length>0){if(ve&&Te){let de=Qe(Re[0]);t.texStorage2D(n.TEXTURE_2D,it,he,de.width,de.height)}for(let de=0,We=Re.length;de<We;de++)le=Re[de],ve?Je&&t.texSubImage2D(n.TEXTURE_2D,de,0,0,xe,V,le):t.texImage2D(n.TEXTURE_2D,de,he,xe,V,le);M.generateMipmaps=!1}else if(ve){if(Te){let de=Qe(ce);t.texStorage2D(n.TEXTURE_2D,it,he,de.width,de.height)}Je&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,xe,V,ce)}else t.texImage2D(n.TEXTURE_2D,0,he,xe,V,ce);C(M)&&M.mipmapsAutoUpdate===!0&&S(pe),be.__version=Me.version,M.onUpdate&&M.onUpdate(M)}I.__version=M.version}function zt(I,M,J){if(M.image.length!==6)return;let pe=Ue(I,M),ue=M.source;t.bindTexture(n.TEXTURE_CUBE_MAP,I.__webglTexture,n.TEXTURE0+J);let Me=i.get(ue);if(ue.version!==Me.__version||pe===!0){t.activeTexture(n.TEXTURE0+J);let be=At.getPrimaries(At.workingColorSpace),ae=M.colorSpace===Us?null:At.getPrimaries(M.colorSpace),ce=M.colorSpace===Us||be===ae?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,M.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,M.premultiplyAlpha),t.pixelStorei(n.UNPACK_ALIGNMENT,M.unpackAlignment),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,ce);let xe=M.isCompressedTexture||M.image[0].isCompressedTexture,V=M.image[0]&&M.image[0].isDataTexture,he=[];for(let Le=0;Le<6;Le++)!xe&&!V?he[Le]=v(M.image[Le],!0,s.maxCubemapSize):he[Le]=V?M.image[Le].image:M.image[Le],he[Le]=$e(M,he[Le]);let le=he[0],Re=r.convert(M.format,M.colorSpace),ve=r.convert(M.type),Te=T(M.internalFormat,Re,ve,M.normalized,M.colorSpace),Je=M.isVideoTexture!==!0,it=Me.__version===void 0||pe===!0,de=ue.dataReady,We=R(M,le);Ie(n.TEXTURE_CUBE_MAP,M);let st;if(M.isDepthTexture){if(Te=_(M.format===Ns,M.type),it)if(Je)t.texStorage2D(n.TEXTURE_CUBE_MAP,1,Te,le.width,le.height);else for(let Le=0;Le<6;Le++)t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,0,Te,le.width,le.height,0,Re,ve,null)}else if(xe){Je&&it&&t.texStorage2D(n.TEXTURE_CUBE_MAP,We,Te,le.width,le.height);for(let Le=0;Le<6;Le++){st=he[Le].mipmaps;for(let pt=0;pt<st.length;pt++){let Zt=st[pt];M.format!==Yi?Re!==null?Je?de&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt,0,0,Zt.width,Zt.height,Re,Zt.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt,Te,Zt.width,Zt.height,0,Zt.data):et("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Je?de&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt,0,0,Zt.width,Zt.height,Re,ve,Zt.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt,Te,Zt.width,Zt.height,0,Re,ve,Zt.data)}}}else{if(st=M.mipmaps,Je&&it){st.length>0&&We++;let Le=Qe(he[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,We,Te,Le.width,Le.height)}for(let Le=0;Le<6;Le++)if(V){Je?de&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,0,0,0,he[Le].width,he[Le].height,Re,ve,he[Le].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,0,Te,he[Le].width,he[Le].height,0,Re,ve,he[Le].data);for(let pt=0;pt<st.length;pt++){let Xn=st[pt].image[Le].image;Je?de&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt+1,0,0,Xn.width,Xn.height,Re,ve,Xn.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt+1,Te,Xn.width,Xn.height,0,Re,ve,Xn.data)}}else{Je?de&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,0,0,0,Re,ve,he[Le]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,0,Te,Re,ve,he[Le]);for(let pt=0;pt<st.length;pt++){let Zt=st[pt];Je?de&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt+1,0,0,Re,ve,Zt.image[Le]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Le,pt+1,Te,Re,ve,Zt.image[Le])}}}C(M)&&M.mipmapsAutoUpdate===!0&&S(n.TEXTURE_CUBE_MAP),Me.__version=ue.version,M.onUpdate&&M.onUpdate(M)}I.__version=M.version}function ct(I,M,J,pe,ue,Me){let be=r.convert(J.format,J.colorSpace),ae=r.convert(J.type),ce=T(J.internalFormat,be,ae,J.normalized,J.colorSpace),xe=i.get(M),V=i.get(J);if(V.__renderTarget=M,!xe.__hasExternalTextures){let he=Math.max(1,M.width>>Me),le=Math.max(1,M.height>>Me);ue===n.TEXTURE_3D||ue===n.TEXTURE_2D_ARRAY?t.texImage3D(ue,Me,ce,he,le,M.depth,0,be,ae,null):t.texImage2D(ue,Me,ce,he,le,0,be,ae,null)}t.bindFramebuffer(n.FRAMEBUFFER,I),Ae(M)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,pe,ue,V.__webglTexture,0,ut(M)):(ue===n.TEXTURE_2D||ue>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&ue<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,pe,ue,V.__webglTexture,Me),t.bindFramebuffer(n.FRAMEBUFFER,null)}function It(I,M,J){if(n.bindRenderbuffer(n.RENDERBUFFER,I),M.depthBuffer){let pe=M.depthTexture,ue=pe&&pe.isDepthTexture?pe.type:null,Me=_(M.stencilBuffer,ue),be=M.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;Ae(M)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ut(M),Me,M.width,M.height):J?n.renderbufferStorageMultisample(n.RENDERBUFFER,ut(M),Me,M.width,M.height):n.renderbufferStorage(n.RENDERBUFFER,Me,M.width,M.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,be,n.RENDERBUFFER,I)}else{let pe=M.textures;for(let ue=0;ue<pe.length;ue++){let Me=pe[ue],be=r.convert(Me.format,Me.colorSpace),ae=r.convert(Me.type),ce=T(Me.internalFormat,be,ae,Me.normalized,Me.colorSpace);Ae(M)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ut(M),ce,M.width,M.height):J?n.renderbufferStorageMultisample(n.RENDERBUFFER,ut(M),ce,M.width,M.height):n.renderbufferStorage(n.RENDERBUFFER,ce,M.width,M.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function je(I,M,J){let pe=M.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(n.FRAMEBUFFER,I),!(M.depthTexture&&M.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let ue=i.get(M.depthTexture);ue.__renderTarget=M;let Me=pe?M.depthTexture.image[0]:M.depthTexture.image;(!ue.__webglTexture||Me.width!==M.width||Me.height!==M.height)&&(Me.width=M.width,Me.height=M.height,M.depthTexture.needsUpdate=!0),pe?Se(M.depthTexture,0):_e(M.depthTexture,0);let be=ue.__webglTexture,ae=ut(M),ce=pe?n.TEXTURE_CUBE_MAP_POSITIVE_X+J:n.TEXTURE_2D,xe=M.depthTexture.format===Ns?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(M.depthTexture.format===Ps)Ae(M)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,xe,ce,be,0,ae):n.framebufferTexture2D(n.FRAMEBUFFER,xe,ce,be,0);else if(M.depthTexture.format===Ns)Ae(M)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,xe,ce,be,0,ae):n.framebufferTexture2D(n.FRAMEBUFFER,xe,ce,be,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function dt(I){let M=i.get(I),J=I.isWebGLCubeRenderTarget===!0;if(M.__boundDepthTexture!==I.depthTexture){let pe=I.depthTexture;if(M.__depthDisposeCallback&&M.__depthDisposeCallback(),pe){let ue=()=>{delete M.__boundDepthTexture,delete M.__depthDisposeCallback,pe.removeEventListener("dispose",ue)};pe.addEventListener("dispose",ue),M.__depthDisposeCallback=ue}M.__boundDepthTexture=pe}if(I.depthTexture&&!M.__autoAllocateDepthBuffer)if(J)for(let pe=0;pe<6;pe++)je(M.__webglFramebuffer[pe],I,pe);else I.texture.mipmaps.length>0?je(M.__webglFramebuffer[0],I,0):je(M.__webglFramebuffer,I,0);else if(J){M.__webglDepthbuffer=[];for(let pe=0;pe<6;pe++)if(t.bindFramebuffer(n.FRAMEBUFFER,M.__webglFramebuffer[pe]),M.__webglDepthbuffer[pe]===void 0)M.__webglDepthbuffer[pe]=n.createRenderbuffer(),It(M.__webglDepthbuffer[pe],I,!1);else{let ue=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Me=M.__webglDepthbuffer[pe];n.bindRenderbuffer(n.RENDERBUFFER,Me),n.framebufferRenderbuffer(n.FRAMEBUFFER,ue,n.RENDERBUFFER,Me)}}else if(I.texture.mipmaps.length>0?t.bindFramebuffer(n.FRAMEBUFFER,M.__webglFramebuffer[0]):t.bindFramebuffer(n.FRAMEBUFFER,M.__webglFramebuffer),M.__webglDepthbuffer===void 0)M.__webglDepthbuffer=n.createRenderbuffer(),It(M.__webglDepthbuffer,I,!1);else{let ue=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Me=M.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,Me),n.framebufferRenderbuffer(n.FRAMEBUFFER,ue,n.RENDERBUFFER,Me)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function mt(I,M,J){let pe=i.get(I);M!==void 0&&ct(pe.__webglFramebuffer,I,I.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),J!==void 0&&dt(I)}function bt(I){let M=I.texture,J=i.get(I),pe=i.get(M);I.addEventListener("dispose",G),W(I);let ue=I.textures,Me=I.isWebGLCubeRenderTarget===!0,be=ue.length>1;if(be||(pe.__webglTexture===void 0&&(pe.__webglTexture=n.createTexture()),pe.__version=M.version,o.memory.textures++),Me){J.__webglFramebuffer=[];for(let ae=0;ae<6;ae++)if(M.mipmaps.length>0){J.__webglFramebuffer[ae]=[];for(let ce=0;ce<M.mipmaps.length;ce++)J.__webglFramebuffer[ae][ce]=n.createFramebuffer()}else J.__webglFramebuffer[ae]=n.createFramebuffer()}else{if(M.mipmaps.length>0){J.__webglFramebuffer=[];for(let ae=0;ae<M.mipmaps.length;ae++)J.__webglFramebuffer[ae]=n.createFramebuffer()}else J.__webglFramebuffer=n.createFramebuffer();if(be)for(let ae=0,ce=ue.length;ae<ce;ae++){let xe=i.get(ue[ae]);xe.__webglTexture===void 0&&(xe.__webglTexture=n.createTexture(),o.memory.textures++)}if(I.samples>0&&Ae(I)===!1){J.__webglMultisampledFramebuffer=n.createFramebuffer(),J.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,J.__webglMultisampledFramebuffer);for(let ae=0;ae<ue.length;ae++){let ce=ue[ae];J.__webglColorRenderbuffer[ae]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,J.__webglColorRenderbuffer[ae]);let xe=r.convert(ce.format,ce.colorSpace),V=r.convert(ce.type),he=T(ce.internalFormat,xe,V,ce.normalized,ce.colorSpace,I.isXRRenderTarget===!0),le=ut(I);n.renderbufferStorageMultisample(n.RENDERBUFFER,le,he,I.width,I.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ae,n.RENDERBUFFER,J.__webglColorRenderbuffer[ae])}n.bindRenderbuffer(n.RENDERBUFFER,null),I.depthBuffer&&(J.__webglDepthRenderbuffer=n.createRenderbuffer(),It(J.__webglDepthRenderbuffer,I,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(Me){t.bindTexture(n.TEXTURE_CUBE_MAP,pe.__webglTexture),Ie(n.TEXTURE_CUBE_MAP,M);for(let ae=0;ae<6;ae++)if(M.mipmaps.length>0)for(let ce=0;ce<M.mipmaps.length;ce++)ct(J.__webglFramebuffer[ae][ce],I,M,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ae,ce);else ct(J.__webglFramebuffer[ae],I,M,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ae,0);C(M)?S(n.TEXTURE_CUBE_MAP):M.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,M.mipmaps.length-1),t.unbindTexture()}else if(be){for(let ae=0,ce=ue.length;ae<ce;ae++){let xe=ue[ae],V=i.get(xe),he=n.TEXTURE_2D;(I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(he=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(he,V.__webglTexture),Ie(he,xe),ct(J.__webglFramebuffer,I,xe,n.COLOR_ATTACHMENT0+ae,he,0),C(xe)&&S(he)}t.unbindTexture()}else{let ae=n.TEXTURE_2D;if((I.isWebGL3DRenderTarget||I.isWebGLArrayRenderTarget)&&(ae=I.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ae,pe.__webglTexture),Ie(ae,M),M.mipmaps.length>0)for(let ce=0;ce<M.mipmaps.length;ce++)ct(J.__webglFramebuffer[ce],I,M,n.COLOR_ATTACHMENT0,ae,ce);else ct(J.__webglFramebuffer,I,M,n.COLOR_ATTACHMENT0,ae,0);C(M)?S(ae):M.mipmaps.length>0&&n.texParameteri(ae,n.TEXTURE_MAX_LEVEL,M.mipmaps.length-1),t.unbindTexture()}I.depthBuffer&&dt(I)}function k(I){let M=I.textures;for(let J=0,pe=M.length;J<pe;J++){let ue=M[J];if(C(ue)&&ue.mipmapsAutoUpdate===!0){let Me=P(I),be=i.get(ue).__webglTexture;t.bindTexture(Me,be),S(Me),t.unbindTexture()}}}let De=[];function tt(I){if(I.samples>0){if(Ae(I)===!1){let M=I.textures,J=I.width,pe=I.height,ue=n.COLOR_BUFFER_BIT,Me=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,be=i.get(I),ae=M.length>1;if(ae)for(let xe=0;xe<M.length;xe++)t.bindFramebuffer(n.FRAMEBUFFER,be.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+xe,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,be.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+xe,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,be.__webglMultisampledFramebuffer),I.texture.mipmaps.length>0?t.bindFramebuffer(n.DRAW_FRAMEBUFFER,be.__webglFramebuffer[0]):t.bindFramebuffer(n.DRAW_FRAMEBUFFER,be.__webglFramebuffer);for(let xe=0;xe<M.length;xe++){if(I.resolveDepthBuffer&&(I.depthBuffer&&(ue|=n.DEPTH_BUFFER_BIT),I.stencilBuffer&&I.resolveStencilBuffer&&(ue|=n.STENCIL_BUFFER_BIT)),ae){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,be.__webglColorRenderbuffer[xe]);let V=i.get(M[xe]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,V,0)}n.blitFramebuffer(0,0,J,pe,0,0,J,pe,ue,n.NEAREST),c===!0&&(De.length=0,De.push(n.COLOR_ATTACHMENT0+xe),I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&De.push(Me),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,De))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),ae)for(let xe=0;xe<M.length;xe++){t.bindFramebuffer(n.FRAMEBUFFER,be.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+xe,n.RENDERBUFFER,be.__webglColorRenderbuffer[xe]);let V=i.get(M[xe]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,be.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+xe,n.TEXTURE_2D,V,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,be.__webglMultisampledFramebuffer)}else if(I.depthBuffer&&I.storeMultisampledDepthBuffer===!1&&c){let M=I.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[M])}}}function ut(I){return Math.min(s.maxSamples,I.samples)}function Ae(I){let M=i.get(I);return I.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&M.__useRenderToTexture!==!1}function Xt(I){let M=o.render.frame;h.get(I)!==M&&(h.set(I,M),I.update())}function $e(I,M){let J=I.colorSpace,pe=I.format,ue=I.type;return I.isCompressedTexture===!0||I.isVideoTexture===!0||J!==ya&&J!==Us&&(At.getTransfer(J)===kt?(pe!==Yi||ue!==bi)&&et("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):at("WebGLTextures: Unsupported texture color space:",J)),M}function Qe(I){return typeof HTMLImageElement<"u"&&I instanceof HTMLImageElement?(l.width=I.naturalWidth||I.width,l.height=I.naturalHeight||I.height):typeof VideoFrame<"u"&&I instanceof VideoFrame?(l.width=I.displayWidth,l.height=I.displayHeight):(l.width=I.width,l.height=I.height),l}this.allocateTextureUnit=oe,this.resetTextureUnits=H,this.getTextureUnits=$,this.setTextureUnits=ne,this.setTexture2D=_e,this.setTexture2DArray=me,this.setTexture3D=Ee,this.setTextureCube=Se,this.rebindTextures=mt,this.setupRenderTarget=bt,this.updateRenderTargetMipmap=k,this.updateMultisampleRenderTarget=tt,this.setupDepthRenderbuffer=dt,this.setupFrameBufferTexture=ct,this.useMultisampledRTT=Ae,this.dispose=U}function uE(n,e){function t(i,s=Us){let r,o=At.getTransfer(s);if(i===bi)return n.UNSIGNED_BYTE;if(i===$c)return n.UNSIGNED_SHORT_4_4_4_4;if(i===Zc)return n.UNSIGNED_SHORT_5_5_5_1;if(i===Gf)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===Wf)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===Vf)return n.BYTE;if(i===Hf)return n.SHORT;if(i===Fo)return n.UNSIGNED_SHORT;if(i===Yc)return n.INT;if(i===Wi)return n.UNSIGNED_INT;if(i===Xi)return n.FLOAT;if(i===qi)return n.HALF_FLOAT;if(i===Xf)return n.ALPHA;if(i===qf)return n.RGB;if(i===Yi)return n.RGBA;if(i===Ps)return n.DEPTH_COMPONENT;if(i===Ns)return n.DEPTH_STENCIL;if(i===Yf)return n.RED;if(i===Jc)return n.RED_INTEGER;if(i===lr)return n.RG;if(i===Kc)return n.RG_INTEGER;if(i===jc)return n.RGBA_INTEGER;if(i===Va||i===Ha||i===Ga||i===Wa)if(o===kt)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(i===Va)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===Ha)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===Ga)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===Wa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(i===Va)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===Ha)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===Ga)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===Wa)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===Qc||i===eh||i===th||i===nh)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(i===Qc)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===eh)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===th)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===nh)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===ih||i===sh||i===rh||i===oh||i===ah||i===Xa||i===lh)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(i===ih||i===sh)return o===kt?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(i===rh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(i===oh)return r.COMPRESSED_R11_EAC;if(i===ah)return r.COMPRESSED_SIGNED_R11_EAC;if(i===Xa)return r.COMPRESSED_RG11_EAC;if(i===lh)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===ch||i===hh||i===uh||i===fh||i===dh||i===ph||i===mh||i===gh||i===_h||i===xh||i===yh||i===vh||i===Sh||i===Mh)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(i===ch)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===hh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===uh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===fh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===dh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===ph)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===mh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===gh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===_h)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===xh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===yh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===vh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===Sh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===Mh)return o===kt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===bh||i===wh||i===Eh)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(i===bh)return o===kt?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===wh)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===Eh)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Th||i===Ah||i===qa||i===Rh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(i===Th)return r.COMPRESSED_RED_RGTC1_EXT;if(i===Ah)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===qa)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===Rh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Ir?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:t}}var fE=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,dE=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,Sd=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){let i=new La(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,i=new cs({vertexShader:fE,fragmentShader:dE,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new ls(new Da(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Md=class extends Gi{constructor(e,t){super();let i=this,s=null,r=1,o=null,a="local-floor",c=1,l=null,h=null,f=null,u=null,p=null,g=null,b=typeof XRWebGLBinding<"u",d=new Sd,m={},v=t.getContextAttributes(),C=null,S=null,P=[],T=[],_=new ft,R=null,W=null,O=new jn;O.viewport=new rn;let L=new jn;L.viewport=new rn;let G=[O,L],X=new Hc,y=null,U=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(se){let _e=P[se];return _e===void 0&&(_e=new Ao,P[se]=_e),_e.getTargetRaySpace()},this.getControllerGrip=function(se){let _e=P[se];return _e===void 0&&(_e=new Ao,P[se]=_e),_e.getGripSpace()},this.getHand=function(se){let _e=P[se];return _e===void 0&&(_e=new Ao,P[se]=_e),_e.getHandSpace()};function D(se){let _e=T.indexOf(se.inputSource);if(_e===-1)return;let me=P[_e];me!==void 0&&(me.update(se.inputSource,se.frame,l||o),me.dispatchEvent({type:se.type,data:se.inputSource}))}function A(){s.removeEventListener("select",D),s.removeEventListener("selectstart",D),s.removeEventListener("selectend",D),s.removeEventListener("squeeze",D),s.removeEventListener("squeezestart",D),s.removeEventListener("squeezeend",D),s.removeEventListener("end",A),s.removeEventListener("inputsourceschange",z);for(let se=0;se<P.length;se++){let _e=T[se];_e!==null&&(T[se]=null,P[se].disconnect(_e))}y=null,U=null,d.reset();for(let se in m)delete m[se];if(e.setRenderTarget(C),p=null,u=null,f=null,s=null,S=null,oe.stop(),i.isPresenting=!1,e.setPixelRatio(R),e.setSize(_.width,_.height,!1),W!==null){let se=W.camera;se.fov=W.fov,se.zoom=W.zoom,se.updateProjectionMatrix(),W=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(se){r=se,i.isPresenting===!0&&et("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(se){a=se,i.isPresenting===!0&&et("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||o},this.setReferenceSpace=function(se){l=se},this.getBaseLayer=function(){return u!==null?u:p},this.getBinding=function(){return f===null&&b&&(f=new XRWebGLBinding(s,t)),f},this.getFrame=function(){return g},this.getSession=function(){return s},this.setSession=async function(se){if(s=se,s!==null){if(C=e.getRenderTarget(),s.addEventListener("select",D),s.addEventListener("selectstart",D),s.addEventListener("selectend",D),s.addEventListener("squeeze",D),s.addEventListener("squeezestart",D),s.addEventListener("squeezeend",D),s.addEventListener("end",A),s.addEventListener("inputsourceschange",z),v.xrCompatible!==!0&&await t.makeXRCompatible(),R=e.getPixelRatio(),e.getSize(_),b&&"createProjectionLayer"in XRWebGLBinding.prototype){let me=null,Ee=null,Se=null;v.depth&&(Se=v.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,me=v.stencil?Ns:Ps,Ee=v.stencil?Ir:Wi);let Ze={colorFormat:t.RGBA8,depthFormat:Se,scaleFactor:r};f=this.getBinding(),u=f.createProjectionLayer(Ze),s.updateRenderState({layers:[u]}),e.setPixelRatio(1),e.setSize(u.textureWidth,u.textureHeight,!1),S=new Si(u.textureWidth,u.textureHeight,{format:Yi,type:bi,depthTexture:new Ls(u.textureWidth,u.textureHeight,Ee,void 0,void 0,void 0,void 0,void 0,void 0,me),stencilBuffer:v.stencil,colorSpace:e.outputColorSpace,samples:v.antialias?4:0,resolveDepthBuffer:u.ignoreDepthValues===!1,resolveStencilBuffer:u.ignoreDepthValues===!1,storeMultisampledDepthBuffer:u.ignoreDepthValues===!1,storeMultisampledStencilBuffer:u.ignoreDepthValues===!1})}else{let me={antialias:v.antialias,alpha:!0,depth:v.depth,stencil:v.stencil,framebufferScaleFactor:r};p=new XRWebGLLayer(s,t,me),s.updateRenderState({baseLayer:p}),e.setPixelRatio(1),e.setSize(p.framebufferWidth,p.framebufferHeight,!1),S=new Si(p.framebufferWidth,p.framebufferHeight,{format:Yi,type:bi,colorSpace:e.outputColorSpace,stencilBuffer:v.stencil,resolveDepthBuffer:p.ignoreDepthValues===!1,resolveStencilBuffer:p.ignoreDepthValues===!1,storeMultisampledDepthBuffer:p.ignoreDepthValues===!1,storeMultisampledStencilBuffer:p.ignoreDepthValues===!1})}S.isXRRenderTarget=!0,this.setFoveation(c),l=null,o=await s.requestReferenceSpace(a),oe.setContext(s),oe.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return d.getDepthTexture()};function z(se){for(let _e=0;_e<se.removed.length;_e++){let me=se.removed[_e],Ee=T.indexOf(me);Ee>=0&&(T[Ee]=null,P[Ee].disconnect(me))}for(let _e=0;_e<se.added.length;_e++){let me=se.added[_e],Ee=T.indexOf(me);if(Ee===-1){for(let Ze=0;Ze<P.length;Ze++)if(Ze>=T.length){T.push(me),Ee=Ze;break}else if(T[Ze]===null){T[Ze]=me,Ee=Ze;break}if(Ee===-1)break}let Se=P[Ee];Se&&Se.connect(me)}}function B(se,_e){_e===null?se.matrixWorld.copy(se.matrix):se.matrixWorld.multiplyMatrices(_e.matrixWorld,se.matrix),se.matrixWorldInverse.copy(se.matrixWorld).invert()}this.updateCamera=function(se){if(s===null)return;let _e=se.near,me=se.far;d.texture!==null&&(d.depthNear>0&&(_e=d.depthNear),d.depthFar>0&&(me=d.depthFar)),X.near=L.near=O.near=_e,X.far=L.far=O.far=me,(y!==X.near||U!==X.far)&&(s.updateRenderState({depthNear:X.near,depthFar:X.far}),y=X.near,U=X.far),X.layers.mask=se.layers.mask|6,O.layers.mask=X.layers.mask&-5,L.layers.mask=X.layers.mask&-3;let Ee=se.parent,Se=X.cameras;B(X,Ee);for(let Ze=0;Ze<Se.length;Ze++)B(Se[Ze],Ee);X.projectionMatrix.copy(O.projectionMatrix),X.projectionMatrixInverse.copy(O.projectionMatrixInverse),W===null&&se.isPerspectiveCamera&&(W={camera:se,fov:se.fov,zoom:se.zoom}),H(se,X,Ee)};function H(se,_e,me){me===null?se.matrix.copy(_e.matrixWorld):(se.matrix.copy(me.matrixWorld),se.matrix.invert(),se.matrix.multiply(_e.matrixWorld)),se.matrix.decompose(se.position,se.quaternion,se.scale),se.updateMatrixWorld(!0),se.projectionMatrix.copy(_e.projectionMatrix),se.projectionMatrixInverse.copy(_e.projectionMatrixInverse),se.isPerspectiveCamera&&(se.fov=Eo*2*Math.atan(1/se.projectionMatrix.elements[5]),se.zoom=1)}this.getCamera=function(){return X},this.getFoveation=function(){if(!(u===null&&p===null))return c},this.setFoveation=function(se){c=se,u!==null&&(u.fixedFoveation=se),p!==null&&p.fixedFoveation!==void 0&&(p.fixedFoveation=se)},this.hasDepthSensing=function(){return d.texture!==null},this.getDepthSensingMesh=function(){return d.getMesh(X)},this.getCameraTexture=function(se){return m[se]};let $=null;function ne(se,_e){if(h=_e.getViewerPose(l||o),g=_e,h!==null){let me=h.views;p!==null&&(e.setRenderTargetFramebuffer(S,p.framebuffer),e.setRenderTarget(S));let Ee=!1;me.length!==X.cameras.length&&(X.cameras.length=0,Ee=!0);for(let Ye=0;Ye<me.length;Ye++){let Ie=me[Ye],Ue=null;if(p!==null)Ue=p.getViewport(Ie);else{let yt=f.getViewSubImage(u,Ie);Ue=yt.viewport,Ye===0&&(e.setRenderTargetTextures(S,yt.colorTexture,yt.depthStencilTexture),e.setRenderTarget(S))}let Ve=G[Ye];Ve===void 0&&(Ve=new jn,Ve.layers.enable(Ye),Ve.viewport=new rn,G[Ye]=Ve),Ve.matrix.fromArray(Ie.transform.matrix),Ve.matrix.decompose(Ve.position,Ve.quaternion,Ve.scale),Ve.projectionMatrix.fromArray(Ie.projectionMatrix),Ve.projectionMatrixInverse.copy(Ve.projectionMatrix).invert(),Ve.viewport.set(Ue.x,Ue.y,Ue.width,Ue.height),Ye===0&&(X.matrix.copy(Ve.matrix),X.matrix.decompose(X.position,X.quaternion,X.scale)),Ee===!0&&X.cameras.push(Ve)}let Se=s.enabledFeatures;if(Se&&Se.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&b){f=i.getBinding();let Ye=f.getDepthInformation(me[0]);Ye&&Ye.isValid&&Ye.texture&&d.init(Ye,s.renderState)}if(Se&&Se.includes("camera-access")&&b){e.state.unbindTexture(),f=i.getBinding();for(let Ye=0;Ye<me.length;Ye++){let Ie=me[Ye].camera;if(Ie){let Ue=m[Ie];Ue||(Ue=new La,m[Ie]=Ue);let Ve=f.getCameraImage(Ie);Ue.sourceTexture=Ve}}}}for(let me=0;me<P.length;me++){let Ee=T[me],Se=P[me];Ee!==null&&Se!==void 0&&Se.update(Ee,_e,l||o)}$&&$(se,_e),_e.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:_e}),g=null}let oe=new L0;oe.setAnimationLoop(ne),this.setAnimationLoop=function(se){$=se},this.dispose=function(){}}},pE=new nn,H0=new lt;H0.set(-1,0,0,0,1,0,0,0,1);function mE(n,e){function t(d,m){d.matrixAutoUpdate===!0&&d.updateMatrix(),m.value.copy(d.matrix)}function i(d,m){m.color.getRGB(d.fogColor.value,sd(n)),m.isFog?(d.fogNear.value=m.near,d.fogFar.value=m.far):m.isFogExp2&&(d.fogDensity.value=m.density)}function s(d,m,v,C,S){m.isNodeMaterial?m.uniformsNeedUpdate=!1:m.isMeshBasicMaterial?r(d,m):m.isMeshLambertMaterial?(r(d,m),m.envMap&&(d.envMapIntensity.value=m.envMapIntensity)):m.isMeshToonMaterial?(r(d,m),f(d,m)):m.isMeshPhongMaterial?(r(d,m),h(d,m),m.envMap&&(d.envMapIntensity.value=m.envMapIntensity)):m.isMeshStandardMaterial?(r(d,m),u(d,m),m.isMeshPhysicalMaterial&&p(d,m,S)):m.isMeshMatcapMaterial?(r(d,m),g(d,m)):m.isMeshDepthMaterial?r(d,m):m.isMeshDistanceMaterial?(r(d,m),b(d,m)):m.isMeshNormalMaterial?r(d,m):m.isLineBasicMaterial?(o(d,m),m.isLineDashedMaterial&&a(d,m)):m.isPointsMaterial?c(d,m,v,C):m.isSpriteMaterial?l(d,m):m.isShadowMaterial?(d.color.value.copy(m.color),d.opacity.value=m.opacity):m.isShaderMaterial&&(m.uniformsNeedUpdate=!1)}function r(d,m){d.opacity.value=m.opacity,m.color&&d.diffuse.value.copy(m.color),m.emissive&&d.emissive.value.copy(m.emissive).multiplyScalar(m.emissiveIntensity),m.map&&(d.map.value=m.map,t(m.map,d.mapTransform)),m.alphaMap&&(d.alphaMap.value=m.alphaMap,t(m.alphaMap,d.alphaMapTransform)),m.bumpMap&&(d.bumpMap.value=m.bumpMap,t(m.bumpMap,d.bumpMapTransform),d.bumpScale.value=m.bumpScale,m.side===ei&&(d.bumpScale.value*=-1)),m.normalMap&&(d.normalMap.value=m.normalMap,t(m.normalMap,d.normalMapTransform),d.normalScale.value.copy(m.normalScale),m.side===ei&&d.normalScale.value.negate()),m.displacementMap&&(d.displacementMap.value=m.displacementMap,t(m.displacementMap,d.displacementMapTransform),d.displacementScale.value=m.displacementScale,d.displacementBias.value=m.displacementBias),m.emissiveMap&&(d.emissiveMap.value=m.emissiveMap,t(m.emissiveMap,d.emissiveMapTransform)),m.specularMap&&(d.specularMap.value=m.specularMap,t(m.specularMap,d.specularMapTransform)),m.alphaTest>0&&(d.alphaTest.value=m.alphaTest);let v=e.get(m),C=v.envMap,S=v.envMapRotation;C&&(d.envMap.value=C,d.envMapRotation.value.setFromMatrix4(pE.makeRotationFromEuler(S)).transpose(),C.isCubeTexture&&C.isRenderTargetTexture===!1&&d.envMapRotation.value.premultiply(H0),d.reflectivity.value=m.reflectivity,d.ior.value=m.ior,d.refractionRatio.value=m.refractionRatio),m.lightMap&&(d.lightMap.value=m.lightMap,d.lightMapIntensity.value=m.lightMapIntensity,t(m.lightMap,d.lightMapTransform)),m.aoMap&&(d.aoMap.value=m.aoMap,d.aoMapIntensity.value=m.aoMapIntensity,t(m.aoMap,d.aoMapTransform))}function o(d,m){d.diffuse.value.copy(m.color),d.opacity.value=m.opacity,m.map&&(d.map.value=m.map,t(m.map,d.mapTransform))}function a(d,m){d.dashSize.value=m.dashSize,d.totalSize.value=m.dashSize+m.gapSize,d.scale.value=m.scale}function c(d,m,v,C){d.diffuse.value.copy(m.color),d.opacity.value=m.opacity,d.size.value=m.size*v,d.scale.value=C*.5,m.map&&(d.map.value=m.map,t(m.map,d.uvTransform)),m.alphaMap&&(d.alphaMap.value=m.alphaMap,t(m.alphaMap,d.alphaMapTransform)),m.alphaTest>0&&(d.alphaTest.value=m.alphaTest)}function l(d,m){d.diffuse.value.copy(m.color),d.opacity.value=m.opacity,d.rotation.value=m.rotation,m.map&&(d.map.value=m.map,t(m.map,d.mapTransform)),m.alphaMap&&(d.alphaMap.value=m.alphaMap,t(m.alphaMap,d.alphaMapTransform)),m.alphaTest>0&&(d.alphaTest.value=m.alphaTest)}function h(d,m){d.specular.value.copy(m.specular),d.shininess.value=Math.max(m.shininess,1e-4)}function f(d,m){m.gradientMap&&(d.gradientMap.value=m.gradientMap)}function u(d,m){d.metalness.value=m.metalness,m.metalnessMap&&(d.metalnessMap.value=m.metalnessMap,t(m.metalnessMap,d.metalnessMapTransform)),d.roughness.value=m.roughness,m.roughnessMap&&(d.roughnessMap.value=m.roughnessMap,t(m.roughnessMap,d.roughnessMapTransform)),m.envMap&&(d.envMapIntensity.value=m.envMapIntensity)}function p(d,m,v){d.ior.value=m.ior,m.diffuseRoughness>0&&(d.diffuseRoughness.value=m.diffuseRoughness,m.diffuseRoughnessMap&&(d.diffuseRoughnessMap.value=m.diffuseRoughnessMap,t(m.diffuseRoughnessMap,d.diffuseRoughnessMapTransform))),m.sheen>0&&(d.sheenColor.value.copy(m.sheenColor).multiplyScalar(m.sheen),d.sheenRoughness.value=m.sheenRoughness,m.sheenColorMap&&(d.sheenColorMap.value=m.sheenColorMap,t(m.sheenColorMap,d.sheenColorMapTransform)),m.sheenRoughnessMap&&(d.sheenRoughnessMap.value=m.sheenRoughnessMap,t(m.sheenRoughnessMap,d.sheenRoughnessMapTransform))),m.clearcoat>0&&(d.clearcoat.value=m.clearcoat,d.clearcoatRoughness.value=m.clearcoatRoughness,m.clearcoatMap&&(d.clearcoatMap.value=m.clearcoatMap,t(m.clearcoatMap,d.clearcoatMapTransform)),m.clearcoatRoughnessMap&&(d.clearcoatRoughnessMap.value=m.clearcoatRoughnessMap,t(m.clearcoatRoughnessMap,d.clearcoatRoughnessMapTransform)),m.clearcoatNormalMap&&(d.clearcoatNormalMap.value=m.clearcoatNormalMap,t(m.clearcoatNormalMap,d.clearcoatNormalMapTransform),d.clearcoatNormalScale.value.copy(m.clearcoatNormalScale),m.side===ei&&d.clearcoatNormalScale.value.negate())),m.dispersion>0&&(d.dispersion.value=m.dispersion),m.retroreflectivity>0&&(d.retroreflectivity.value=m.retroreflectivity),m.iridescence>0&&(d.iridescence.value=m.iridescence,d.iridescenceIOR.value=m.iridescenceIOR,d.iridescenceThicknessMinimum.value=m.iridescenceThicknessMinimum,d.iridescenceThicknessMaximum.value=m.iridescenceThicknessMaximum,m.iridescenceMap&&(d.iridescenceMap.value=m.iridescenceMap,t(m.iridescenceMap,d.iridescenceMapTransform)),m.iridescenceThicknessMap&&(d.iridescenceThicknessMap.value=m.iridescenceThicknessMap,t(m.iridescenceThicknessMap,d.iridescenceThicknessMapTransform))),m.transmission>0&&(d.transmission.value=m.transmission,d.transmissionSamplerMap.value=v.texture,d.transmissionSamplerSize.value.set(v.width,v.height),m.transmissionMap&&(d.transmissionMap.value=m.transmissionMap,t(m.transmissionMap,d.transmissionMapTransform)),d.thickness.value=m.thickness,m.thicknessMap&&(d.thicknessMap.value=m.thicknessMap,t(m.thicknessMap,d.thicknessMapTransform)),d.attenuationDistance.value=m.attenuationDistance,d.attenuationColor.value.copy(m.attenuationColor)),m.anisotropy>0&&(d.anisotropyVector.value.set(m.anisotropy*Math.cos(m.anisotropyRotation),m.anisotropy*Math.sin(m.anisotropyRotation)),m.anisotropyMap&&(d.anisotropyMap.value=m.anisotropyMap,t(m.anisotropyMap,d.anisotropyMapTransform))),d.specularIntensity.value=m.specularIntensity,d.specularColor.value.copy(m.specularColor),m.specularColorMap&&(d.specularColorMap.value=m.specularColorMap,t(m.specularColorMap,d.specularColorMapTransform)),m.specularIntensityMap&&(d.specularIntensityMap.value=m.specularIntensityMap,t(m.specularIntensityMap,d.specularIntensityMapTransform))}function g(d,m){m.matcap&&(d.matcap.value=m.matcap)}function b(d,m){let v=e.get(m).light;d.referencePosition.value.setFromMatrixPosition(v.matrixWorld),d.nearDistance.value=v.shadow.camera.near,d.farDistance.value=v.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:s}}function gE(n,e,t,i){let s={},r={};function o(v,C){let S=C.program;i.uniformBlockBinding(v,S,s[v.id])}function a(v,C){let S=s[v.id];S===void 0&&(g(v),S=c(v),s[v.id]=S,v.addEventListener("dispose",d));let P=C.program;i.updateUBOMapping(v,P);let T=e.render.frame;r[v.id]!==T&&(l(v),r[v.id]=T)}function c(v){let C=n.createBuffer(),S=v.__size,P=v.usage;return n.bindBuffer(n.UNIFORM_BUFFER,C),n.bufferData(n.UNIFORM_BUFFER,S,P),n.bindBuffer(n.UNIFORM_BUFFER,null),C}function l(v){let C=s[v.id],S=v.uniforms,P=v.__cache;n.bindBuffer(n.UNIFORM_BUFFER,C);for(let T=0,_=S.length;T<_;T++){let R=S[T];if(Array.isArray(R))for(let W=0,O=R.length;W<O;W++)h(R[W],T,W,P);else h(R,T,0,P)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function h(v,C,S,P){if(u(v,C,S,P)===!0){let T=v.__offset,_=v.value;if(Array.isArray(_)){let R=0;for(let W=0;W<_.length;W++){let O=_[W],L=b(O,!0);f(O,v.__data,R),R+=L.storage/Float32Array.BYTES_PER_ELEMENT}}else f(_,v.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,T,v.__data)}}function f(v,C,S){typeof v=="number"||typeof v=="boolean"?C[S]=v:v.isMatrix3?(C[S]=v.elements[0],C[S+1]=v.elements[1],C[S+2]=v.elements[2],C[S+3]=0,C[S+4]=v.elements[3],C[S+5]=v.elements[4],C[S+6]=v.elements[5],C[S+7]=0,C[S+8]=v.elements[6],C[S+9]=v.elements[7],C[S+10]=v.elements[8],C[S+11]=0):ArrayBuffer.isView(v)?C.set(v.subarray(0,C.length-S),S):v.toArray(C,S)}function u(v,C,S,P){let T=v.value,_=C+"_"+S;if(Array.isArray(T)){P[_]===void 0&&(P[_]=[]);let R=P[_],W=!1;for(let O=0;O<T.length;O++)p(T[O],R,O)===!0&&(W=!0);return W}return p(T,P,_)}function p(v,C,S){if(C[S]===void 0)return typeof v=="number"||typeof v=="boolean"?C[S]=v:ArrayBuffer.isView(v)?C[S]=v.slice():C[S]=v.clone(),!0;{let P=C[S];if(typeof v=="number"||typeof v=="boolean"){if(P!==v)return C[S]=v,!0}else{if(ArrayBuffer.isView(v))return!0;if(P.equals(v)===!1)return P.copy(v),!0}}return!1}function g(v){let C=v.uniforms,S=0,P=16;for(let _=0,R=C.length;_<R;_++){let W=Array.isArray(C[_])?C[_]:[C[_]];for(let O=0,L=W.length;O<L;O++){let G=W[O],X=Array.isArray(G.value)?G.value:[G.value],y=Array.isArray(C[_])||Array.isArray(G.value),U=S;for(let A=0,z=X.length;A<z;A++){let B=X[A],H=b(B,y),$=S%P,ne=$%H.boundary,oe=$+ne;S+=ne,oe!==0&&P-oe<H.storage&&(S+=P-oe),A===0&&(U=S),S+=H.storage}let D=G.type==="int"?Int32Array:G.type==="uint"?Uint32Array:Float32Array;G.__data=new D((S-U)/Float32Array.BYTES_PER_ELEMENT),G.__offset=U}}let T=S%P;return T>0&&(S+=P-T),v.__size=S,v.__cache={},this}function b(v,C){let S={boundary:0,storage:0};return typeof v=="number"||typeof v=="boolean"?(S.boundary=4,S.storage=4):v.isVector2?(S.boundary=8,S.storage=8):v.isVector3||v.isColor?(S.boundary=16,S.storage=12):v.isVector4?(S.boundary=16,S.storage=16):v.isMatrix3?(S.boundary=16,S.storage=48):v.isMatrix4?(S.boundary=16,S.storage=64):v.isTexture?et("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(v)?(S.boundary=16,S.storage=v.byteLength):et("WebGLRenderer: Unsupported uniform value type.",v),C===!0&&(S.boundary=16,S.storage=Math.ceil(S.storage/16)*16),S}function d(v){let C=v.target;C.removeEventListener("dispose",d),n.deleteBuffer(s[C.id]),delete s[C.id],delete r[C.id]}function m(){for(let v in s)n.deleteBuffer(s[v]);s={},r={}}return{bind:o,update:a,dispose:m}}var _E=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),fs=null;function xE(){return fs===null&&(fs=new bc(_E,16,16,lr,qi),fs.name="DFG_LUT",fs.minFilter=Qn,fs.magFilter=Qn,fs.wrapS=as,fs.wrapT=as,fs.generateMipmaps=!1,fs.needsUpdate=!0),fs}var Lh=class{constructor(e={}){let{canvas:t=t0(),context:i=null,depth:s=!0,stencil:r=!1,alpha:o=!1,antialias:a=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:f=!1,reversedDepthBuffer:u=!1,outputBufferType:p=bi}=e;this.isWebGLRenderer=!0;let g;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");g=i.getContextAttributes().alpha}else g=o;let b=p,d=new Set([jc,Kc,Jc]),m=new Set([bi,Wi,Fo,Ir,$c,Zc]),v=new Uint32Array(4),C=new Int32Array(4),S={textures:[],min:[],max:[],resolution:[]},P=null,T=null,_=[],R=[],W=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=us,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let O=this,L=!1,G=null,X=null,y=null,U=null;this._outputColorSpace=_i;let D=0,A=0,z=null,B=-1,H=null,$=new rn,ne=new rn,oe=null,se=new _t(0),_e=0,me=t.width,Ee=t.height,Se=1,Ze=null,rt=null,Ye=new rn(0,0,me,Ee),Ie=new rn(0,0,me,Ee),Ue=!1,Ve=new Ar,yt=new wc,Pt=!1,zt=!1,ct=new nn,It=new ee,je=new rn,dt={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},mt=!1;function bt(){return z===null?Se:1}let k=i;function De(E,Y){return t.getContext(E,Y)}let tt,ut,Ae,Xt,$e,Qe,I,M,J,pe,ue,Me,be,ae,ce,xe,V,he,le,Re,ve,Te,Je;try{let E={alpha:!0,depth:s,stencil:r,antialias:a,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:h,failIfMajorPerformanceCaveat:f};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${"187"}`),t.addEventListener("webglcontextlost",We,!1),t.addEventListener("webglcontextrestored",st,!1),t.addEventListener("webglcontextcreationerror",Le,!1),k===null){let Y="webgl2";if(k=De(Y,E),k===null)throw De(Y)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}it()}catch(E){throw t.removeEventListener("webglcontextlost",We,!1),t.removeEventListener("webglcontextrestored",st,!1),t.removeEventListener("webglcontextcreationerror",Le,!1),at("WebGLRenderer: "+E.message),E}function it(){tt=new Cb(k),tt.init(),ve=new uE(k,tt),ut=new xb(k,tt,e,ve),Ae=new cE(k,tt),ut.reversedDepthBuffer&&u&&Ae.buffers.depth.setReversed(!0),X=k.createFramebuffer(),y=k.createFramebuffer(),U=k.createFramebuffer(),Xt=new Lb(k),$e=new Zw,Qe=new hE(k,tt,Ae,$e,ut,ve,Xt),I=new Rb(O),M=new Nv(k),Te=new gb(k,M),J=new Pb(k,M,Xt,Te),pe=new Nb(k,J,M,Te,Xt),he=new Db(k,ut,Qe),ce=new yb($e),ue=new $w(O,I,tt,ut,Te,ce),Me=new mE(O,$e),be=new Kw,ae=new iE(tt),V=new mb(O,I,Ae,pe,g,c),xe=new lE(O,pe,ut),Je=new gE(k,Xt,ut,Ae),le=new _b(k,tt,Xt),Re=new Ib(k,tt,Xt),Xt.programs=ue.programs,O.capabilities=ut,O.extensions=tt,O.properties=$e,O.renderLists=be,O.shadowMap=xe,O.state=Ae,O.info=Xt}b!==bi&&(W=new Fb(b,t.width,t.height,a,s,r));let de=new Md(O,k);this.xr=de,this.getContext=function(){return k},this.getContextAttributes=function(){return k.getContextAttributes()},this.forceContextLoss=function(){let E=tt.get("WEBGL_lose_context");E&&E.loseContext()},this.forceContextRestore=function(){let E=tt.get("WEBGL_lose_context");E&&E.restoreContext()},this.getPixelRatio=function(){return Se},this.setPixelRatio=function(E){E!==void 0&&(Se=E,this.setSize(me,Ee,!1))},this.getSize=function(E){return E.set(me,Ee)},this.setSize=function(E,Y,re=!0){if(de.isPresenting){et("WebGLRenderer: Can't change size while VR device is presenting.");return}me=E,Ee=Y,t.width=Math.floor(E*Se),t.height=Math.floor(Y*Se),re===!0&&(t.style.width=E+"px",t.style.height=Y+"px"),W!==null&&W.setSize(t.width,t.height),this.setViewport(0,0,E,Y)},this.getDrawingBufferSize=function(E){return E.set(me*Se,Ee*Se).floor()},this.setDrawingBufferSize=function(E,Y,re){me=E,Ee=Y,Se=re,t.width=Math.floor(E*re),t.height=Math.floor(Y*re),this.setViewport(0,0,E,Y)},this.setEffects=function(E){if(b===bi){at("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(E){for(let Y=0;Y<E.length;Y++)if(E[Y].isOutputPass===!0){et("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}W.setEffects(E||[])},this.getCurrentViewport=function(E){return E.copy($)},this.getViewport=function(E){return E.copy(Ye)},this.setViewport=function(E,Y,re,K){E.isVector4?Ye.set(E.x,E.y,E.z,E.w):Ye.set(E,Y,re,K),Ae.viewport($.copy(Ye).multiplyScalar(bt()).round())},this.getScissor=function(E){return E.copy(Ie)},this.setScissor=function(E,Y,re,K){E.isVector4?Ie.set(E.x,E.y,E.z,E.w):Ie.set(E,Y,re,K),Ae.scissor(ne.copy(Ie).multiplyScalar(bt()).round())},this.getScissorTest=function(){return Ue},this.setScissorTest=function(E){Ae.setScissorTest(Ue=E)},this.setOpaqueSort=function(E){Ze=E},this.setTransparentSort=function(E){rt=E},this.getClearColor=function(E){return E.copy(V.getClearColor())},this.setClearColor=function(){V.setClearColor(...arguments)},this.getClearAlpha=function(){return V.getClearAlpha()},this.setClearAlpha=function(){V.setClearAlpha(...arguments)},this.clear=function(E=!0,Y=!0,re=!0){let K=0;if(E){let j=!1;if(z!==null){let Ce=z.texture.format;j=d.has(Ce)}if(j){let Ce=z.texture.type,Ne=m.has(Ce),Pe=V.getClearColor(),Fe=V.getClearAlpha(),qe=Pe.r,ot=Pe.g,vt=Pe.b;Ne?(v[0]=qe,v[1]=ot,v[2]=vt,v[3]=Fe,k.clearBufferuiv(k.COLOR,0,v)):(C[0]=qe,C[1]=ot,C[2]=vt,C[3]=Fe,k.clearBufferiv(k.COLOR,0,C))}else K|=k.COLOR_BUFFER_BIT}Y&&(K|=k.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),re&&(K|=k.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),K!==0&&k.clear(K)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(E){E.setRenderer(this),G=E},this.dispose=function(){t.removeEventListener("webglcontextlost",We,!1),t.removeEventListener("webglcontextrestored",st,!1),t.removeEventListener("webglcontextcreationerror",Le,!1),V.dispose(),be.dispose(),ae.dispose(),Qe.dispose(),$e.dispose(),I.dispose(),pe.dispose(),J.dispose(),Te.dispose(),Je.dispose(),ue.dispose(),de.dispose(),de.removeEventListener("sessionstart",Ka),de.removeEventListener("sessionend",Zi),ps.stop()};function We(E){E.preventDefault(),Qf("WebGLRenderer: Context Lost."),L=!0}function st(){Qf("WebGLRenderer: Context Restored."),L=!1;let E=Xt.autoReset,Y=xe.enabled,re=xe.autoUpdate,K=xe.needsUpdate,j=xe.type;it(),Xt.autoReset=E,xe.enabled=Y,xe.autoUpdate=re,xe.needsUpdate=K,xe.type=j}function Le(E){at("WebGLRenderer: A WebGL context could not be created. Reason: ",E.statusMessage)}function pt(E){let Y=E.target;Y.removeEventListener("dispose",pt),Zt(Y)}function Zt(E){Xn(E),$e.remove(E)}function Xn(E){let Y=$e.get(E).programs;Y!==void 0&&(Y.forEach(function(re){ue.releaseProgram(re)}),E.isShaderMaterial&&ue.releaseShaderCache(E))}this.renderBufferDirect=function(E,Y,re,K,j,Ce){Y===null&&(Y=dt);let Ne=j.isMesh&&j.matrixWorld.determinantAffine()<0,Pe=Go(E,Y,re,K,j);Ae.setMaterial(K,Ne);let Fe=re.index,qe=1;if(K.wireframe===!0){if(Fe=J.getWireframeAttribute(re),Fe===void 0)return;qe=2}let ot=re.drawRange,vt=re.attributes.position,Xe=ot.start*qe,St=(ot.start+ot.count)*qe;Ce!==null&&(Xe=Math.max(Xe,Ce.start*qe),St=Math.min(St,(Ce.start+Ce.count)*qe)),Fe!==null?(Xe=Math.max(Xe,0),St=Math.min(St,Fe.count)):vt!=null&&(Xe=Math.max(Xe,0),St=Math.min(St,vt.count));let sn=St-Xe;if(sn<0||sn===1/0)return;Te.setup(j,K,Pe,re,Fe);let Vt,Ht=le;if(Fe!==null&&(Vt=M.get(Fe),Ht=Re,Ht.setIndex(Vt)),j.isMesh)K.wireframe===!0?(Ae.setLineWidth(K.wireframeLinewidth*bt()),Ht.setMode(k.LINES)):Ht.setMode(k.TRIANGLES);else if(j.isLine){let bn=K.linewidth;bn===void 0&&(bn=1),Ae.setLineWidth(bn*bt()),j.isLineSegments?Ht.setMode(k.LINES):j.isLineLoop?Ht.setMode(k.LINE_LOOP):Ht.setMode(k.LINE_STRIP)}else j.isPoints?Ht.setMode(k.POINTS):j.isSprite&&Ht.setMode(k.TRIANGLES);if(j.isBatchedMesh)if(tt.get("WEBGL_multi_draw"))Ht.renderMultiDraw(j._multiDrawStarts,j._multiDrawCounts,j._multiDrawCount);else{let bn=j._multiDrawStarts,He=j._multiDrawCounts,gn=j._multiDrawCount,Et=Fe?M.get(Fe).bytesPerElement:1,gs=$e.get(K).currentProgram.getUniforms();for(let _n=0;_n<gn;_n++)gs.setValue(k,"_gl_DrawID",_n),Ht.render(bn[_n]/Et,He[_n])}else if(j.isInstancedMesh)Ht.renderInstances(Xe,sn,j.count);else if(re.isInstancedBufferGeometry){let bn=re._maxInstanceCount!==void 0?re._maxInstanceCount:1/0,He=Math.min(re.instanceCount,bn);Ht.renderInstances(Xe,sn,He)}else Ht.render(Xe,sn)};function zo(E,Y,re,K){G!==null&&E.isNodeMaterial&&G.setObject(K,E),Pt===!0&&ce.setState(E,re,!1),E.transparent===!0&&E.side===hs&&E.forceSinglePass===!1?(E.side=ei,E.needsUpdate=!0,Ji(E,Y,K),E.side=ar,E.needsUpdate=!0,Ji(E,Y,K),E.side=hs):Ji(E,Y,K)}this.compile=function(E,Y,re=null){re===null&&(re=E),G!==null&&G.renderStart(E,Y,re),T=ae.get(re),T.init(Y),R.push(T),re.traverseVisible(function(j){j.isLight&&j.layers.test(Y.layers)&&(T.pushLight(j),j.castShadow&&T.pushShadow(j))}),E!==re&&E.traverseVisible(function(j){j.isLight&&j.layers.test(Y.layers)&&(T.pushLight(j),j.castShadow&&T.pushShadow(j))}),T.setupLights(),G!==null&&G.updateLights(T.state.lightsArray),zt=this.localClippingEnabled,Pt=ce.init(this.clippingPlanes,zt),Pt===!0&&ce.setGlobalState(this.clippingPlanes,Y),G!==null&&xe.render(T.state.shadowsArray,re,Y);let K=new Set;return E.traverse(function(j){if(!(j.isMesh||j.isPoints||j.isLine||j.isSprite))return;let Ce=j.material;if(Ce)if(Array.isArray(Ce))for(let Ne=0;Ne<Ce.length;Ne++){let Pe=Ce[Ne];zo(Pe,re,Y,j),K.add(Pe)}else zo(Ce,re,Y,j),K.add(Ce)}),T=R.pop(),G!==null&&G.renderEnd(),K},this.compileAsync=function(E,Y,re=null){let K=this.compile(E,Y,re);return new Promise(j=>{function Ce(){if(K.forEach(function(Ne){let Fe=$e.get(Ne).currentProgram;(Fe===void 0||Fe.isReady())&&K.delete(Ne)}),K.size===0){j(E);return}setTimeout(Ce,10)}tt.get("KHR_parallel_shader_compile")!==null?Ce():setTimeout(Ce,10)})};let Nr=null;function Hh(E){Nr&&Nr(E)}function Ka(){ps.stop()}function Zi(){ps.start()}let ps=new L0;ps.setAnimationLoop(Hh),typeof self<"u"&&ps.setContext(self),this.setAnimationLoop=function(E){Nr=E,de.setAnimationLoop(E),E===null?ps.stop():ps.start()},de.addEventListener("sessionstart",Ka),de.addEventListener("sessionend",Zi),this.render=function(E,Y){if(Y!==void 0&&Y.isCamera!==!0){at("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(L===!0)return;G!==null&&G.renderStart(E,Y);let re=de.enabled===!0&&de.isPresenting===!0,K=W!==null&&(z===null||re)&&W.begin(O,z);if(E.matrixWorldAutoUpdate===!0&&E.updateMatrixWorld(),Y.parent===null&&Y.matrixWorldAutoUpdate===!0&&Y.updateMatrixWorld(),de.enabled===!0&&de.isPresenting===!0&&(W===null||W.isCompositing()===!1)&&(de.cameraAutoUpdate===!0&&de.updateCamera(Y),Y=de.getCamera()),E.isScene===!0&&E.onBeforeRender(O,E,Y,z),T=ae.get(E,R.length),T.init(Y),T.state.textureUnits=Qe.getTextureUnits(),R.push(T),ct.multiplyMatrices(Y.projectionMatrix,Y.matrixWorldInverse),Y.isArrayCamera?yt.setFromArrayCamera(Y):Ve.setFromProjectionMatrix(ct,Li,Y.reversedDepth),zt=this.localClippingEnabled,Pt=ce.init(this.clippingPlanes,zt),P=be.get(E,_.length),P.init(),_.push(P),this.info.render.frame++,de.enabled===!0&&de.isPresenting===!0){let Ne=O.xr.getDepthSensingMesh();Ne!==null&&ms(Ne,Y,-1/0,O.sortObjects)}ms(E,Y,0,O.sortObjects),P.finish(),G!==null&&G.updateLights(T.state.lightsArray),O.sortObjects===!0&&P.sort(Ze,rt),mt=de.enabled===!1||de.isPresenting===!1||de.hasDepthSensing()===!1,mt&&V.addToRenderList(P,E),this.info.autoReset===!0&&this.info.reset(),Pt===!0&&ce.beginShadows();let j=T.state.shadowsArray;if(xe.render(j,E,Y),Pt===!0&&ce.endShadows(),(K&&W.hasRenderPass())===!1){let Ne=P.opaque,Pe=P.transmissive;if(T.setupLights(),Y.isArrayCamera){let Fe=Y.cameras;if(Pe.length>0)for(let qe=0,ot=Fe.length;qe<ot;qe++){let vt=Fe[qe];Di(Ne,Pe,E,vt)}mt&&V.render(E);for(let qe=0,ot=Fe.length;qe<ot;qe++){let vt=Fe[qe];Vo(P,E,vt,vt.viewport)}}else Pe.length>0&&Di(Ne,Pe,E,Y),mt&&V.render(E),Vo(P,E,Y)}z!==null&&A===0&&(Qe.updateMultisampleRenderTarget(z),Qe.updateRenderTargetMipmap(z)),K&&W.end(O),E.isScene===!0&&E.onAfterRender(O,E,Y),Te.resetDefaultState(),B=-1,H=null,R.pop(),R.length>0?(T=R[R.length-1],Qe.setTextureUnits(T.state.textureUnits),Pt===!0&&ce.setGlobalState(O.clippingPlanes,T.state.camera)):T=null,_.pop(),_.length>0?P=_[_.length-1]:P=null,G!==null&&G.renderEnd()};function ms(E,Y,re,K){if(E.visible===!1)return;if(E.layers.test(Y.layers)){if(E.isGroup)re=E.renderOrder;else if(E.isLOD)E.autoUpdate===!0&&E.update(Y);else if(E.isLight)T.pushLight(E),E.castShadow&&T.pushShadow(E);else if(E.isSprite){let Ne=Y.isArrayCamera?yt:Ve;if(!E.frustumCulled||E.intersectsFrustum(Ne)){K&&je.setFromMatrixPosition(E.matrixWorld).applyMatrix4(ct);let Pe=pe.update(E),Fe=E.material;Fe.visible&&P.push(E,Pe,Fe,re,je.z,null,Y)}}else if(E.isMesh||E.isLine||E.isPoints){let Ne=Y.isArrayCamera?yt:Ve;if(!E.frustumCulled||E.intersectsFrustum(Ne)){let Pe=pe.update(E),Fe=E.material;if(K&&(E.boundingSphere!==void 0?(E.boundingSphere===null&&E.computeBoundingSphere(),je.copy(E.boundingSphere.center)):(Pe.boundingSphere===null&&Pe.computeBoundingSphere(),je.copy(Pe.boundingSphere.center)),je.applyMatrix4(E.matrixWorld).applyMatrix4(ct)),Array.isArray(Fe)){let qe=Pe.groups;for(let ot=0,vt=qe.length;ot<vt;ot++){let Xe=qe[ot],St=Fe[Xe.materialIndex];St&&St.visible&&P.push(E,Pe,St,re,je.z,Xe,Y)}}else Fe.visible&&P.push(E,Pe,Fe,re,je.z,null,Y)}}}let Ce=E.children;for(let Ne=0,Pe=Ce.length;Ne<Pe;Ne++)ms(Ce[Ne],Y,re,K)}function Vo(E,Y,re,K){let{opaque:j,transmissive:Ce,transparent:Ne}=E;T.setupLightsView(re),Pt===!0&&ce.setGlobalState(O.clippingPlanes,re),K&&Ae.viewport($.copy(K)),j.length>0&&on(j,Y,re),Ce.length>0&&on(Ce,Y,re),Ne.length>0&&on(Ne,Y,re),Ae.buffers.depth.setTest(!0),Ae.buffers.depth.setMask(!0),Ae.buffers.color.setMask(!0),Ae.setPolygonOffset(!1)}function Di(E,Y,re,K){if((re.isScene===!0?re.overrideMaterial:null)!==null)return;if(T.state.transmissionRenderTarget[K.id]===void 0){let Xe=tt.has("EXT_color_buffer_half_float")||tt.has("EXT_color_buffer_float");T.state.transmissionRenderTarget[K.id]=new Si(1,1,{generateMipmaps:!0,type:Xe?qi:bi,minFilter:Ds,samples:Math.max(4,ut.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:At.workingColorSpace})}let Ce=T.state.transmissionRenderTarget[K.id],Ne=K.viewport||$;Ce.setSize(Ne.z*O.transmissionResolutionScale,Ne.w*O.transmissionResolutionScale);let Pe=O.getRenderTarget(),Fe=O.getActiveCubeFace(),qe=O.getActiveMipmapLevel();O.setRenderTarget(Ce),O.getClearColor(se),_e=O.getClearAlpha(),_e<1&&O.setClearColor(16777215,.5),O.clear(),mt&&V.render(re);let ot=O.toneMapping;O.toneMapping=us;let vt=K.viewport;if(K.viewport!==void 0&&(K.viewport=void 0),T.setupLightsView(K),Pt===!0&&ce.setGlobalState(O.clippingPlanes,K),on(E,re,K),Qe.updateMultisampleRenderTarget(Ce),Qe.updateRenderTargetMipmap(Ce),tt.has("WEBGL_multisampled_render_to_texture")===!1){let Xe=!1;for(let St=0,sn=Y.length;St<sn;St++){let Vt=Y[St],{object:Ht,geometry:bn,material:He,group:gn}=Vt;if(He.side===hs&&Ht.layers.test(K.layers)){let Et=He.side;He.side=ei,He.needsUpdate=!0,dn(Ht,re,K,bn,He,gn),He.side=Et,He.needsUpdate=!0,Xe=!0}}Xe===!0&&(Qe.updateMultisampleRenderTarget(Ce),Qe.updateRenderTargetMipmap(Ce))}O.setRenderTarget(Pe,Fe,qe),O.setClearColor(se,_e),vt!==void 0&&(K.viewport=vt),O.toneMapping=ot}function on(E,Y,re){let K=Y.isScene===!0?Y.overrideMaterial:null;for(let j=0,Ce=E.length;j<Ce;j++){let Ne=E[j],{object:Pe,geometry:Fe,group:qe}=Ne,ot=Ne.material;ot.allowOverride===!0&&K!==null&&(ot=K),Pe.layers.test(re.layers)&&dn(Pe,Y,re,Fe,ot,qe)}}function dn(E,Y,re,K,j,Ce){G!==null&&j.isNodeMaterial&&G.setObject(E,j),E.onBeforeRender(O,Y,re,K,j,Ce),E.modelViewMatrix.multiplyMatrices(re.matrixWorldInverse,E.matrixWorld),E.normalMatrix.getNormalMatrix(E.modelViewMatrix),j.onBeforeRender(O,Y,re,K,E,Ce),j.transparent===!0&&j.side===hs&&j.forceSinglePass===!1?(j.side=ei,j.needsUpdate=!0,O.renderBufferDirect(re,Y,K,j,E,Ce),j.side=ar,j.needsUpdate=!0,O.renderBufferDirect(re,Y,K,j,E,Ce),j.side=hs):O.renderBufferDirect(re,Y,K,j,E,Ce),E.onAfterRender(O,Y,re,K,j,Ce)}function pn(E){let Y=0;for(let re of E)re.texture!==null&&Y++;return Y}function Ji(E,Y,re){Y.isScene!==!0&&(Y=dt);let K=$e.get(E),j=T.state.lights,Ce=T.state.shadowsArray,Ne=j.state.version,Pe=ue.getParameters(E,j.state,Ce,Y,re,T.state.lightProbeGridArray),Fe=ue.getProgramCacheKey(Pe),qe=K.programs;K.environment=E.isMeshStandardMaterial||E.isMeshLambertMaterial||E.isMeshPhongMaterial?Y.environment:null,K.fog=Y.fog;let ot=E.isMeshStandardMaterial||E.isMeshLambertMaterial&&!E.envMap||E.isMeshPhongMaterial&&!E.envMap;K.envMap=I.get(E.envMap||K.environment,ot),K.envMapRotation=K.environment!==null&&E.envMap===null?Y.environmentRotation:E.envMapRotation,qe===void 0&&(E.addEventListener("dispose",pt),qe=new Map,K.programs=qe,K.programVariants=new Map);let vt=qe.get(Fe);if(vt!==void 0){if(K.currentProgram===vt&&K.lightsStateVersion===Ne)return Ho(E,Pe),vt}else Pe.uniforms=ue.getUniforms(E),G!==null&&E.isNodeMaterial&&G.build(E,re,Pe),E.onBeforeCompile(Pe,O),vt=ue.acquireProgram(Pe,Fe),qe.set(Fe,vt),K.uniforms=Pe.uniforms;let Xe=K.uniforms;return(!E.isShaderMaterial&&!E.isRawShaderMaterial||E.clipping===!0)&&(Xe.clippingPlanes=ce.uniform),Ho(E,Pe),K.needsLights=Os(E),K.lightsStateVersion=Ne,K.needsLights&&(Xe.ambientLightColor.value=j.state.ambient,Xe.lightProbe.value=j.state.probe,Xe.sunLights.value=j.state.sun,Xe.sunLightShadows.value=j.state.sunShadow,Xe.directionalLights.value=j.state.directional,Xe.directionalLightShadows.value=j.state.directionalShadow,Xe.spotLights.value=j.state.spot,Xe.spotLightShadows.value=j.state.spotShadow,Xe.rectAreaLights.value=j.state.rectArea,Xe.ltc_1.value=j.state.rectAreaLTC1,Xe.ltc_2.value=j.state.rectAreaLTC2,Xe.pointLights.value=j.state.point,Xe.pointLightShadows.value=j.state.pointShadow,Xe.hemisphereLights.value=j.state.hemi,Xe.sunShadowMatrix.value=j.state.sunShadowMatrix,Xe.sunShadowCascade.value=j.state.sunShadowCascade,Xe.directionalShadowMatrix.value=j.state.directionalShadowMatrix,Xe.spotLightMatrix.value=j.state.spotLightMatrix,Xe.spotLightMap.value=j.state.spotLightMap,Xe.pointShadowMatrix.value=j.state.pointShadowMatrix),K.numLightProbeGrids=pn(T.state.lightProbeGridArray),K.currentProgram=vt,K.uniformsList=null,vt}function ri(E,Y,re,K,j){let Ce=$e.get(E),Ne=Ce.currentProgram.id+","+K+","+j,Pe=Ce.programVariants.get(Ne);return Pe===void 0?(Pe=Ji(E,Y,re),Ce.programVariants.set(Ne,Pe)):(Ce.currentProgram=Pe,Ce.uniformsList=null,Ce.outputColorSpace=K,Ce.toneMapping=j),Pe}function Fs(E){if(E.uniformsList===null){let Y=E.currentProgram.getUniforms();E.uniformsList=Bo.seqWithValue(Y.seq,E.uniforms)}return E.uniformsList}function Ho(E,Y){let re=$e.get(E);re.outputColorSpace=Y.outputColorSpace,re.batching=Y.batching,re.batchingColor=Y.batchingColor,re.instancing=Y.instancing,re.instancingColor=Y.instancingColor,re.instancingMorph=Y.instancingMorph,re.skinning=Y.skinning,re.morphTargets=Y.morphTargets,re.morphNormals=Y.morphNormals,re.morphColors=Y.morphColors,re.morphTargetsCount=Y.morphTargetsCount,re.numClippingPlanes=Y.numClippingPlanes,re.numIntersection=Y.numClipIntersection,re.vertexAlphas=Y.vertexAlphas,re.vertexTangents=Y.vertexTangents,re.toneMapping=Y.toneMapping}function Go(E,Y,re,K,j){Y.isScene!==!0&&(Y=dt),Qe.resetTextureUnits();let Ce=Y.fog,Ne=K.isMeshStandardMaterial||K.isMeshLambertMaterial||K.isMeshPhongMaterial?Y.environment:null,Pe=z===null?O.outputColorSpace:z.isXRRenderTarget===!0?z.texture.colorSpace:At.workingColorSpace,Fe=K.isMeshStandardMaterial||K.isMeshLambertMaterial&&!K.envMap||K.isMeshPhongMaterial&&!K.envMap,qe=I.get(K.envMap||Ne,Fe),ot=K.vertexColors===!0&&!!re.attributes.color&&re.attributes.color.itemSize===4,vt=!!re.attributes.tangent&&(!!K.normalMap||K.anisotropy>0),Xe=!!re.morphAttributes.position,St=!!re.morphAttributes.normal,sn=!!re.morphAttributes.color,Vt=us;K.toneMapped&&(z===null||z.isXRRenderTarget===!0)&&(Vt=O.toneMapping);let Ht=re.morphAttributes.position||re.morphAttributes.normal||re.morphAttributes.color,bn=Ht!==void 0?Ht.length:0,He=$e.get(K),gn=T.state.lights;if(Pt===!0&&(zt===!0||E!==H)){let Gt=E===H&&K.id===B;ce.setState(K,E,Gt)}let Et=!1,gs=!1;K.version===He.__version?He.needsLights&&He.lightsStateVersion!==gn.state.version||j.isBatchedMesh&&He.batching===!1||!j.isBatchedMesh&&He.batching===!0||j.isBatchedMesh&&He.batchingColor===!0&&j._colorsTexture===null||j.isBatchedMesh&&He.batchingColor===!1&&j._colorsTexture!==null||j.isInstancedMesh&&He.instancing===!1||!j.isInstancedMesh&&He.instancing===!0||j.isSkinnedMesh&&He.skinning===!1||!j.isSkinnedMesh&&He.skinning===!0||j.isInstancedMesh&&He.instancingColor===!0&&j.instanceColor===null||j.isInstancedMesh&&He.instancingColor===!1&&j.instanceColor!==null||j.isInstancedMesh&&He.instancingMorph===!0&&j.morphTexture===null||j.isInstancedMesh&&He.instancingMorph===!1&&j.morphTexture!==null||He.envMap!==qe||K.fog===!0&&He.fog!==Ce||He.numClippingPlanes!==void 0&&(He.numClippingPlanes!==ce.numPlanes||He.numIntersection!==ce.numIntersection)||He.vertexAlphas!==ot||He.vertexTangents!==vt||He.morphTargets!==Xe||He.morphNormals!==St||He.morphColors!==sn||He.morphTargetsCount!==bn||He.numLightProbeGrids!==pn(T.state.lightProbeGridArray)?Et=!0:(He.outputColorSpace!==Pe||He.toneMapping!==Vt)&&(gs=!0):(Et=!0,He.__version=K.version);let _n=He.currentProgram;(Et===!0||gs===!0)&&(_n=gs===!0?ri(K,Y,j,Pe,Vt):Ji(K,Y,j),G&&K.isNodeMaterial&&G.onUpdateProgram(K,_n,He));let Or=!1,Ki=!1,_s=!1,gt=_n.getUniforms(),an=He.uniforms;if(Ae.useProgram(_n.program)&&(Or=!0,Ki=!0,_s=!0),K.id!==B&&(B=K.id,Ki=!0),Or||H!==E){Ae.buffers.depth.getReversed()&&E.reversedDepth!==!0&&(E._reversedDepth=!0,E.updateProjectionMatrix()),gt.setValue(k,"projectionMatrix",E.projectionMatrix),gt.setValue(k,"viewMatrix",E.matrixWorldInverse);let xn=gt.map.cameraPosition;xn!==void 0&&xn.setValue(k,It.setFromMatrixPosition(E.matrixWorld)),ut.logarithmicDepthBuffer&&gt.setValue(k,"logDepthBufFC",2/(Math.log(E.far+1)/Math.LN2)),(K.isMeshPhongMaterial||K.isMeshToonMaterial||K.isMeshLambertMaterial||K.isMeshBasicMaterial||K.isMeshStandardMaterial||K.isShaderMaterial)&&gt.setValue(k,"isOrthographic",E.isOrthographicCamera===!0),H!==E&&(H=E,Ki=!0,_s=!0)}if(He.needsLights&&(gn.state.sunShadowMap.length>0&&gt.setValue(k,"sunShadowMap",gn.state.sunShadowMap,Qe),gn.state.directionalShadowMap.length>0&&gt.setValue(k,"directionalShadowMap",gn.state.directionalShadowMap,Qe),gn.state.spotShadowMap.length>0&&gt.setValue(k,"spotShadowMap",gn.state.spotShadowMap,Qe),gn.state.pointShadowMap.length>0&&gt.setValue(k,"pointShadowMap",gn.state.pointShadowMap,Qe)),j.isSkinnedMesh){gt.setOptional(k,j,"bindMatrix"),gt.setOptional(k,j,"bindMatrixInverse");let Gt=j.skeleton;Gt&&(Gt.boneTexture===null&&Gt.computeBoneTexture(),gt.setValue(k,"boneTexture",Gt.boneTexture,Qe))}j.isBatchedMesh&&(gt.setOptional(k,j,"batchingTexture"),gt.setValue(k,"batchingTexture",j._matricesTexture,Qe),gt.setOptional(k,j,"batchingIdTexture"),gt.setValue(k,"batchingIdTexture",j._indirectTexture,Qe),gt.setOptional(k,j,"batchingColorTexture"),j._colorsTexture!==null&&gt.setValue(k,"batchingColorTexture",j._colorsTexture,Qe));let qn=re.morphAttributes;if((qn.position!==void 0||qn.normal!==void 0||qn.color!==void 0)&&he.update(j,re,_n),(Ki||He.receiveShadow!==j.receiveShadow)&&(He.receiveShadow=j.receiveShadow,gt.setValue(k,"receiveShadow",j.receiveShadow)),(K.isMeshStandardMaterial||K.isMeshLambertMaterial||K.isMeshPhongMaterial)&&K.envMap===null&&Y.environment!==null&&(an.envMapIntensity.value=Y.environmentIntensity),an.dfgLUT!==void 0&&(an.dfgLUT.value=xE()),Ki){if(gt.setValue(k,"toneMappingExposure",O.toneMappingExposure),He.needsLights&&Ur(an,_s),Ce&&K.fog===!0&&Me.refreshFogUniforms(an,Ce),Me.refreshMaterialUniforms(an,K,Se,Ee,T.state.transmissionRenderTarget[E.id]),He.needsLights&&He.numLightProbeGrids>0){let Gt=S,xn=0;for(let zn of T.state.lightProbeGridArray)zn.texture!==null&&(Gt.textures[xn]=zn.texture,Gt.min[xn]=zn.boundingBox.min,Gt.max[xn]=zn.boundingBox.max,Gt.resolution[xn]=zn.resolution,xn++);for(let zn in Gt)Gt[zn].length=xn;an.probesSH.value=Gt.textures,an.probesMin.value=Gt.min,an.probesMax.value=Gt.max,an.probesResolution.value=Gt.resolution}Bo.upload(k,Fs(He),an,Qe)}if(K.isShaderMaterial&&K.uniformsNeedUpdate===!0&&(Bo.upload(k,Fs(He),an,Qe),K.uniformsNeedUpdate=!1),K.isSpriteMaterial&&gt.setValue(k,"center",j.center),gt.setValue(k,"modelViewMatrix",j.modelViewMatrix),gt.setValue(k,"normalMatrix",j.normalMatrix),gt.setValue(k,"modelMatrix",j.matrixWorld),K.uniformsGroups!==void 0){let Gt=K.uniformsGroups;for(let xn=0,zn=Gt.length;xn<zn;xn++){let ja=Gt[xn];Je.update(ja,_n),Je.bind(ja,_n)}}return _n}function Ur(E,Y){E.ambientLightColor.needsUpdate=Y,E.lightProbe.needsUpdate=Y,E.sunLights.needsUpdate=Y,E.sunLightShadows.needsUpdate=Y,E.directionalLights.needsUpdate=Y,E.directionalLightShadows.needsUpdate=Y,E.pointLights.needsUpdate=Y,E.pointLightShadows.needsUpdate=Y,E.spotLights.needsUpdate=Y,E.spotLightShadows.needsUpdate=Y,E.rectAreaLights.needsUpdate=Y,E.hemisphereLights.needsUpdate=Y}function Os(E){return E.isMeshLambertMaterial||E.isMeshToonMaterial||E.isMeshPhongMaterial||E.isMeshStandardMaterial||E.isShadowMaterial||E.isShaderMaterial&&E.lights===!0}this.getActiveCubeFace=function(){return D},this.getActiveMipmapLevel=function(){return A},this.getRenderTarget=function(){return z},this.setRenderTargetTextures=function(E,Y,re){let K=$e.get(E);K.__autoAllocateDepthBuffer=E.resolveDepthBuffer===!1,K.__autoAllocateDepthBuffer===!1&&(K.__useRenderToTexture=!1),$e.get(E.texture).__webglTexture=Y,$e.get(E.depthTexture).__webglTexture=K.__autoAllocateDepthBuffer?void 0:re,K.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(E,Y){let re=$e.get(E);re.__webglFramebuffer=Y,re.__useDefaultFramebuffer=Y===void 0},this.setRenderTarget=function(E,Y=0,re=0){z=E,D=Y,A=re;let K=null,j=!1,Ce=!1;if(E){let Pe=$e.get(E);if(Pe.__useDefaultFramebuffer!==void 0){Ae.bindFramebuffer(k.FRAMEBUFFER,Pe.__webglFramebuffer),$.copy(E.viewport),ne.copy(E.scissor),oe=E.scissorTest,Ae.viewport($),Ae.scissor(ne),Ae.setScissorTest(oe),B=-1;return}else if(Pe.__webglFramebuffer===void 0)Qe.setupRenderTarget(E);else if(Pe.__hasExternalTextures)Qe.rebindTextures(E,$e.get(E.texture).__webglTexture,$e.get(E.depthTexture).__webglTexture);else if(E.depthBuffer){let ot=E.depthTexture;if(Pe.__boundDepthTexture!==ot){if(ot!==null&&$e.has(ot)&&(E.width!==ot.image.width||E.height!==ot.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Qe.setupDepthRenderbuffer(E)}}let Fe=E.texture;(Fe.isData3DTexture||Fe.isDataArrayTexture||Fe.isCompressedArrayTexture)&&(Ce=!0);let qe=$e.get(E).__webglFramebuffer;E.isWebGLCubeRenderTarget?(Array.isArray(qe[Y])?K=qe[Y][re]:K=qe[Y],j=!0):E.samples>0&&Qe.useMultisampledRTT(E)===!1?K=$e.get(E).__webglMultisampledFramebuffer:Array.isArray(qe)?K=qe[re]:K=qe,$.copy(E.viewport),ne.copy(E.scissor),oe=E.scissorTest}else $.copy(Ye).multiplyScalar(Se).floor(),ne.copy(Ie).multiplyScalar(Se).floor(),oe=Ue;if(re!==0&&(K=X),Ae.bindFramebuffer(k.FRAMEBUFFER,K)&&Ae.drawBuffers(E,K),Ae.viewport($),Ae.scissor(ne),Ae.setScissorTest(oe),j){let Pe=$e.get(E.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_CUBE_MAP_POSITIVE_X+Y,Pe.__webglTexture,re)}else if(Ce){let Pe=Y;for(let Fe=0;Fe<E.textures.length;Fe++){let qe=$e.get(E.textures[Fe]);k.framebufferTextureLayer(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0+Fe,qe.__webglTexture,re,Pe)}}else if(E!==null&&re!==0){let Pe=$e.get(E.texture);k.framebufferTexture2D(k.FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,Pe.__webglTexture,re)}B=-1};function Fr(E){let Y=$e.get(E);return(Y.__readFormat!==E.format||Y.__readType!==E.type)&&(Y.__readFormat=E.format,Y.__readType=E.type,Y.__formatReadable=ut.textureFormatReadable(E.format),Y.__typeReadable=ut.textureTypeReadable(E.type)),Y}this.readRenderTargetPixels=function(E,Y,re,K,j,Ce,Ne,Pe=0){if(!(E&&E.isWebGLRenderTarget)){at("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Fe=$e.get(E).__webglFramebuffer;if(E.isWebGLCubeRenderTarget&&Ne!==void 0&&(Fe=Fe[Ne],Array.isArray(Fe)&&(Fe=Fe[0])),Fe){Ae.bindFramebuffer(k.FRAMEBUFFER,Fe);try{let qe=E.textures[Pe],ot=qe.format,vt=qe.type;E.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+Pe);let Xe=Fr(qe);if(Xe.__formatReadable===!1){at("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(Xe.__typeReadable===!1){at("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}Y>=0&&Y<=E.width-K&&re>=0&&re<=E.height-j&&k.readPixels(Y,re,K,j,ve.convert(ot),ve.convert(vt),Ce)}finally{let qe=z!==null?$e.get(z).__webglFramebuffer:null;Ae.bindFramebuffer(k.FRAMEBUFFER,qe)}}},this.readRenderTargetPixelsAsync=async function(E,Y,re,K,j,Ce,Ne,Pe=0){if(!(E&&E.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Fe=$e.get(E).__webglFramebuffer;if(E.isWebGLCubeRenderTarget&&Ne!==void 0&&(Fe=Fe[Ne],Array.isArray(Fe)&&(Fe=Fe[0])),Fe)if(Y>=0&&Y<=E.width-K&&re>=0&&re<=E.height-j){Ae.bindFramebuffer(k.FRAMEBUFFER,Fe);let qe=E.textures[Pe],ot=qe.format,vt=qe.type;E.textures.length>1&&k.readBuffer(k.COLOR_ATTACHMENT0+Pe);let Xe=Fr(qe);if(Xe.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(Xe.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let St=k.createBuffer();k.bindBuffer(k.PIXEL_PACK_BUFFER,St),k.bufferData(k.PIXEL_PACK_BUFFER,Ce.byteLength,k.STREAM_READ),k.readPixels(Y,re,K,j,ve.convert(ot),ve.convert(vt),0),k.bindBuffer(k.PIXEL_PACK_BUFFER,null);let sn=z!==null?$e.get(z).__webglFramebuffer:null;Ae.bindFramebuffer(k.FRAMEBUFFER,sn);let Vt=k.fenceSync(k.SYNC_GPU_COMMANDS_COMPLETE,0);return k.flush(),await i0(k,Vt,4),k.bindBuffer(k.PIXEL_PACK_BUFFER,St),k.getBufferSubData(k.PIXEL_PACK_BUFFER,0,Ce),k.bindBuffer(k.PIXEL_PACK_BUFFER,null),k.deleteBuffer(St),k.deleteSync(Vt),Ce}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(E,Y=null,re=0){let K=Math.pow(2,-re),j=Math.floor(E.image.width*K),Ce=Math.floor(E.image.height*K),Ne=Y!==null?Y.x:0,Pe=Y!==null?Y.y:0;Qe.setTexture2D(E,0),k.copyTexSubImage2D(k.TEXTURE_2D,re,0,0,Ne,Pe,j,Ce),Ae.unbindTexture()},this.copyTextureToTexture=function(E,Y,re=null,K=null,j=0,Ce=0){let Ne,Pe,Fe,qe,ot,vt,Xe,St,sn,Vt=E.isCompressedTexture?E.mipmaps[Ce]:E.image;if(re!==null)Ne=re.max.x-re.min.x,Pe=re.max.y-re.min.y,Fe=re.isBox3?re.max.z-re.min.z:1,qe=re.min.x,ot=re.min.y,vt=re.isBox3?re.min.z:0;else{let gt=Math.pow(2,-j);Ne=Math.floor(Vt.width*gt),Pe=Math.floor(Vt.height*gt),E.isDataArrayTexture?Fe=Vt.depth:E.isData3DTexture?Fe=Math.floor(Vt.depth*gt):Fe=1,qe=0,ot=0,vt=0}K!==null?(Xe=K.x,St=K.y,sn=K.z):(Xe=0,St=0,sn=0);let Ht=ve.convert(Y.format),bn=ve.convert(Y.type),He;Y.isData3DTexture?(Qe.setTexture3D(Y,0),He=k.TEXTURE_3D):Y.isDataArrayTexture||Y.isCompressedArrayTexture?(Qe.setTexture2DArray(Y,0),He=k.TEXTURE_2D_ARRAY):(Qe.setTexture2D(Y,0),He=k.TEXTURE_2D),Ae.activeTexture(k.TEXTURE0),Ae.pixelStorei(k.UNPACK_FLIP_Y_WEBGL,Y.flipY),Ae.pixelStorei(k.UNPACK_PREMULTIPLY_ALPHA_WEBGL,Y.premultiplyAlpha),Ae.pixelStorei(k.UNPACK_ALIGNMENT,Y.unpackAlignment);let gn=Ae.getParameter(k.UNPACK_ROW_LENGTH),Et=Ae.getParameter(k.UNPACK_IMAGE_HEIGHT),gs=Ae.getParameter(k.UNPACK_SKIP_PIXELS),_n=Ae.getParameter(k.UNPACK_SKIP_ROWS),Or=Ae.getParameter(k.UNPACK_SKIP_IMAGES);Ae.pixelStorei(k.UNPACK_ROW_LENGTH,Vt.width),Ae.pixelStorei(k.UNPACK_IMAGE_HEIGHT,Vt.height),Ae.pixelStorei(k.UNPACK_SKIP_PIXELS,qe),Ae.pixelStorei(k.UNPACK_SKIP_ROWS,ot),Ae.pixelStorei(k.UNPACK_SKIP_IMAGES,vt);let Ki=E.isDataArrayTexture||E.isData3DTexture,_s=Y.isDataArrayTexture||Y.isData3DTexture;if(E.isDepthTexture){let gt=$e.get(E),an=$e.get(Y),qn=$e.get(gt.__renderTarget),Gt=$e.get(an.__renderTarget);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,qn.__webglFramebuffer),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,Gt.__webglFramebuffer);for(let xn=0;xn<Fe;xn++)Ki&&(k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,$e.get(E).__webglTexture,j,vt+xn),k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,$e.get(Y).__webglTexture,Ce,sn+xn)),k.blitFramebuffer(qe,ot,qe+Ne,ot+Pe,Xe,St,Xe+Ne,St+Pe,k.DEPTH_BUFFER_BIT,k.NEAREST);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,null),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else if(j!==0||E.isRenderTargetTexture||$e.has(E)){let gt=$e.get(E),an=$e.get(Y);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,y),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,U);for(let qn=0;qn<Fe;qn++)Ki?k.framebufferTextureLayer(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,gt.__webglTexture,j,vt+qn):k.framebufferTexture2D(k.READ_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,gt.__webglTexture,j),_s?k.framebufferTextureLayer(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,an.__webglTexture,Ce,sn+qn):k.framebufferTexture2D(k.DRAW_FRAMEBUFFER,k.COLOR_ATTACHMENT0,k.TEXTURE_2D,an.__webglTexture,Ce),j!==0?k.blitFramebuffer(qe,ot,qe+Ne,ot+Pe,Xe,St,Xe+Ne,St+Pe,k.COLOR_BUFFER_BIT,k.NEAREST):_s?k.copyTexSubImage3D(He,Ce,Xe,St,sn+qn,qe,ot,Ne,Pe):k.copyTexSubImage2D(He,Ce,Xe,St,qe,ot,Ne,Pe);Ae.bindFramebuffer(k.READ_FRAMEBUFFER,null),Ae.bindFramebuffer(k.DRAW_FRAMEBUFFER,null)}else _s?E.isDataTexture||E.isData3DTexture?k.texSubImage3D(He,Ce,Xe,St,sn,Ne,Pe,Fe,Ht,bn,Vt.data):Y.isCompressedArrayTexture?k.compressedTexSubImage3D(He,Ce,Xe,St,sn,Ne,Pe,Fe,Ht,Vt.data):k.texSubImage3D(He,Ce,Xe,St,sn,Ne,Pe,Fe,Ht,bn,Vt):E.isDataTexture?k.texSubImage2D(k.TEXTURE_2D,Ce,Xe,St,Ne,Pe,Ht,bn,Vt.data):E.isCompressedTexture?k.compressedTexSubImage2D(k.TEXTURE_2D,Ce,Xe,St,Vt.width,Vt.height,Ht,Vt.data):k.texSubImage2D(k.TEXTURE_2D,Ce,Xe,St,Ne,Pe,Ht,bn,Vt);Ae.pixelStorei(k.UNPACK_ROW_LENGTH,gn),Ae.pixelStorei(k.UNPACK_IMAGE_HEIGHT,Et),Ae.pixelStorei(k.UNPACK_SKIP_PIXELS,gs),Ae.pixelStorei(k.UNPACK_SKIP_ROWS,_n),Ae.pixelStorei(k.UNPACK_SKIP_IMAGES,Or),Ce===0&&Y.generateMipmaps===!0&&Y.mipmapsAutoUpdate===!0&&k.generateMipmap(He),Ae.unbindTexture()},this.initRenderTarget=function(E){$e.get(E).__webglFramebuffer===void 0&&Qe.setupRenderTarget(E)},this.initTexture=function(E){E.isCubeTexture?Qe.setTextureCube(E,0):E.isData3DTexture?Qe.setTexture3D(E,0):E.isDataArrayTexture||E.isCompressedArrayTexture?Qe.setTexture2DArray(E,0):Qe.setTexture2D(E,0),Ae.unbindTexture()},this.resetState=function(){D=0,A=0,z=null,Ae.reset(),Te.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Li}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorSpace=At._getDrawingBufferColorSpace(e),t.unpackColorSpace=At._getUnpackColorSpace()}};var G0={type:"change"},wd={type:"start"},X0={type:"end"},Uh=new tr,W0=new xi,vE=Math.cos(70*id.DEG2RAD),Cn=new ee,si=2*Math.PI,Ft={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},bd=1e-6,Fh=class extends Ba{constructor(e,t=null){super(e,t),this.state=Ft.NONE,this.target=new ee,this.cursor=new ee,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:rr.ROTATE,MIDDLE:rr.DOLLY,RIGHT:rr.PAN},this.touches={ONE:or.ROTATE,TWO:or.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new ee,this._lastQuaternion=new vi,this._lastTargetPosition=new ee,this._quat=new vi().setFromUnitVectors(e.up,new ee(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Lo,this._sphericalDelta=new Lo,this._scale=1,this._panOffset=new ee,this._rotateStart=new ft,this._rotateEnd=new ft,this._rotateDelta=new ft,this._panStart=new ft,this._panEnd=new ft,this._panDelta=new ft,this._dollyStart=new ft,this._dollyEnd=new ft,this._dollyDelta=new ft,this._dollyDirection=new ee,this._mouse=new ft,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=ME.bind(this),this._onPointerDown=SE.bind(this),this._onPointerUp=bE.bind(this),this._onContextMenu=PE.bind(this),this._onMouseWheel=TE.bind(this),this._onKeyDown=AE.bind(this),this._onTouchStart=RE.bind(this),this._onTouchMove=CE.bind(this),this._onMouseDown=wE.bind(this),this._onMouseMove=EE.bind(this),this._interceptControlDown=IE.bind(this),this._interceptControlUp=LE.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Ft.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(G0),this.update(),this.state=Ft.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){let t=this.object.position;Cn.copy(t).sub(this.target),Cn.applyQuaternion(this._quat),this._spherical.setFromVector3(Cn),this.autoRotate&&this.state===Ft.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(i)&&isFinite(s)&&(i<-Math.PI?i+=si:i>Math.PI&&(i-=si),s<-Math.PI?s+=si:s>Math.PI&&(s-=si),i<=s?this._spherical.theta=Math.max(i,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+s)/2?Math.max(i,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let o=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=o!=this._spherical.radius}if(Cn.setFromSpherical(this._spherical),Cn.applyQuaternion(this._quatInverse),t.copy(this.target).add(Cn),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let o=null;if(this.object.isPerspectiveCamera){let a=Cn.length();o=this._clampDistance(a*this._scale);let c=a-o;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),r=!!c}else if(this.object.isOrthographicCamera){let a=new ee(this._mouse.x,this._mouse.y,0);a.unproject(this.object);let c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=c!==this.object.zoom;let l=new ee(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(a),this.object.updateMatrixWorld(),o=Cn.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;o!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(o).add(this.object.position):(Uh.origin.copy(this.object.position),Uh.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(Uh.direction))<vE?this.object.lookAt(this.target):(W0.setFromNormalAndCoplanarPoint(this.object.up,this.target),Uh.intersectPlane(W0,this.target))))}else if(this.object.isOrthographicCamera){let o=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),o!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>bd||8*(1-this._lastQuaternion.dot(this.object.quaternion))>bd||this._lastTargetPosition.distanceToSquared(this.target)>bd?(this.dispatchEvent(G0),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?si/60*this.autoRotateSpeed*e:si/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){Cn.setFromMatrixColumn(t,0),Cn.multiplyScalar(-e),this._panOffset.add(Cn)}_panUp(e,t){this.screenSpacePanning===!0?Cn.setFromMatrixColumn(t,1):(Cn.setFromMatrixColumn(t,0),Cn.crossVectors(this.object.up,Cn)),Cn.multiplyScalar(e),this._panOffset.add(Cn)}_pan(e,t){let i=this.domElement;if(this.object.isPerspectiveCamera){let s=this.object.position;Cn.copy(s).sub(this.target);let r=Cn.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/i.clientHeight,this.object.matrix),this._panUp(2*t*r/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let i=this.domElement.getBoundingClientRect(),s=e-i.left,r=t-i.top,o=i.width,a=i.height;this._mouse.x=s/o*2-1,this._mouse.y=-(r/a)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(si*this._rotateDelta.x/t.clientHeight),this._rotateUp(si*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(si*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-si*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(si*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-si*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(i,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(i,s)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let i=this._getSecondPointerPosition(e),s=.5*(e.pageX+i.x),r=.5*(e.pageY+i.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(si*this._rotateDelta.x/t.clientHeight),this._rotateUp(si*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(i,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let o=(e.pageX+t.x)*.5,a=(e.pageY+t.y)*.5;this._updateZoomParameters(o,a)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new ft,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,i={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}};function SE(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function ME(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function bE(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(X0),this.state=Ft.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function wE(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case rr.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=Ft.DOLLY;break;case rr.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Ft.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Ft.ROTATE}break;case rr.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Ft.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Ft.PAN}break;default:this.state=Ft.NONE}this.state!==Ft.NONE&&this.dispatchEvent(wd)}function EE(n){switch(this.state){case Ft.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case Ft.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case Ft.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function TE(n){this.enabled===!1||this.enableZoom===!1||this.state!==Ft.NONE||(n.preventDefault(),this.dispatchEvent(wd),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(X0))}function AE(n){this.enabled!==!1&&this._handleKeyDown(n)}function RE(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case or.ROTATE:if(this.enableRotate===!1){this.state=Ft.NONE;break}this._handleTouchStartRotate(n),this.state=Ft.TOUCH_ROTATE;break;case or.PAN:if(this.enablePan===!1){this.state=Ft.NONE;break}this._handleTouchStartPan(n),this.state=Ft.TOUCH_PAN;break;default:this.state=Ft.NONE}break;case 2:switch(this.touches.TWO){case or.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=Ft.TOUCH_DOLLY_PAN;break;case or.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=Ft.TOUCH_DOLLY_ROTATE;break;default:this.state=Ft.NONE}break;default:this.state=Ft.NONE}this.state!==Ft.NONE&&this.dispatchEvent(wd)}function CE(n){switch(this._trackPointer(n),this.state){case Ft.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case Ft.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case Ft.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case Ft.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=Ft.NONE}}function PE(n){this.enabled!==!1&&n.preventDefault()}function IE(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function LE(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var Oh=256,Ed=(()=>{let n=new Float32Array(Oh*3),e=new _t;for(let t=0;t<Oh;t++)e.setHSL(.66*(1-t/(Oh-1)),.9,.55),n.set([e.r,e.g,e.b],t*3);return n})(),Bh=class{constructor(e){this.parent=e;this.renderer=new Lh({antialias:!1,preserveDrawingBuffer:!0}),this.renderer.setPixelRatio(Math.min(window.devicePixelRatio||1,2)),this.renderer.setClearColor(725014),e.appendChild(this.renderer.domElement),this.camera=new jn(60,1,.05,200),this.camera.up.set(0,0,1),this.camera.position.set(-8,-8,7),this.controls=new Fh(this.camera,this.renderer.domElement),this.controls.addEventListener("change",()=>this.dirty=!0),this.points=new Ca(this.geometry,new Co({size:.06,vertexColors:!0})),this.points.frustumCulled=!1,this.scene.add(this.points);let t=new Fa(20,20,3885658,1844785);t.rotation.x=Math.PI/2,this.scene.add(t,new Oa(1)),this.ro=new ResizeObserver(()=>this.resize()),this.ro.observe(e);let i=()=>{this.dirty&&this.render(),this.raf=requestAnimationFrame(i)};this.raf=requestAnimationFrame(i)}parent;renderer;scene=new Ea;camera;controls;geometry=new ii;points;capacity=0;cloud;dirty=!0;raf=0;ro;colourBy="height";onShown=null;pending=!1;pendingStamp=null;lastCount=0;resize(){let e=this.parent.clientWidth,t=Math.max(200,this.parent.clientHeight-4);this.renderer.setSize(e,t,!0),this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.dirty=!0}show(e){let t=performance.now();this.cloud=gp(e,this.cloud);let i=this.cloud.count;i>this.capacity&&(this.capacity=Math.max(i,Math.ceil(this.capacity*1.5)),this.geometry.setAttribute("position",new yi(new Float32Array(this.capacity*3),3)),this.geometry.setAttribute("color",new yi(new Float32Array(this.capacity*3),3)));let s=this.geometry.getAttribute("position"),r=this.geometry.getAttribute("color");return s.array.set(this.cloud.positions.subarray(0,i*3)),this.colour(this.cloud,r.array,i),s.needsUpdate=!0,r.needsUpdate=!0,this.geometry.setDrawRange(0,i),this.lastCount=i,this.pending=!0,this.pendingStamp=yl(e.header),Ot.busyMs.cloudUnpack+=performance.now()-t,this.dirty=!0,i}colour(e,t,i){let s=this.colourBy==="intensity"&&i>0&&!Number.isNaN(e.intensity[0]),r=1/0,o=-1/0;for(let c=0;c<i;c++){let l=s?e.intensity[c]:e.positions[c*3+2];l<r&&(r=l),l>o&&(o=l)}let a=(Oh-1)/(o>r?o-r:1);for(let c=0;c<i;c++){let l=Math.round(((s?e.intensity[c]:e.positions[c*3+2])-r)*a)*3;t[c*3]=Ed[l],t[c*3+1]=Ed[l+1],t[c*3+2]=Ed[l+2]}}render(){this.dirty=!1;let e=performance.now();this.renderer.render(this.scene,this.camera),Ot.busyMs.cloudRender+=performance.now()-e,this.pending&&this.onShown&&this.onShown(this.pendingStamp),this.pending=!1}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.controls.dispose(),this.geometry.dispose(),this.points.material.dispose(),this.renderer.dispose(),this.renderer.domElement.remove()}};function Dr(n,e,t,i){(n instanceof HTMLButtonElement||n instanceof HTMLSelectElement)&&(n.disabled=!0),n.title=t,i.textContent=`Disabled: ${t}`,i.className="why",Ot.disabled[e]=t}function q0(n,e,t,i,s,r){let o=`/${t}/`,a=ye("div","task nav");a.appendChild(ye("h3","","Navigation goal"));let c=ye("p","muted","Looking for the robot's navigation action…"),l=ye("progress");l.max=1,l.value=0;let h=ye("div","navstate",""),f=Gs("Cancel goal","danger");f.disabled=!0,a.append(c,l,h,f);let u=ye("div","task init");u.appendChild(ye("h3","","Initial pose"));let p=Gs("Set initial pose: click the map"),g=ye("p","muted",`publishes geometry_msgs/msg/PoseWithCovarianceStamped on ${o}initialpose`);u.append(p,g);let b=ye("div","task svc");b.appendChild(ye("h3","","Call a service"));let d=ye("select"),m=ye("form","svcform"),v=ye("div","svcout"),C=ye("p","muted","Listing the services you may call…");b.append(d,C,m,v),n.append(a,u,b);let S="goal",P=null,T=null,_=!1,R=!1;i.onClick=async(L,G)=>{if(S==="init"){if(S="goal",p.classList.remove("armed"),!R)return;let X=s()?.yaw??0;e.publish(`${o}initialpose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{pose:{position:{x:L,y:G,z:0},orientation:{x:0,y:0,z:Math.sin(X/2),w:Math.cos(X/2)}},covariance:new Array(36).fill(0)}},y=>Dr(p,"initialpose",y,g)),g.textContent=`initial pose sent: (${mn(L,2)}, ${mn(G,2)})`;return}T?W(L,G):_&&(i.goal={x:L,y:G},i.invalidate(),e.publish(`${o}goal_pose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{position:{x:L,y:G,z:0},orientation:{x:0,y:0,z:0,w:1}}},X=>Dr(a,"goal",X,c)),h.textContent=`goal published on ${o}goal_pose: (${mn(L,2)}, ${mn(G,2)})`)};function W(L,G){if(!T)return;let X=T;i.goal={x:L,y:G},i.invalidate();let y=s(),U=y?Math.hypot(y.x-L,y.y-G):1;l.value=0,h.textContent=`goal (${mn(L,2)}, ${mn(G,2)}) sent to ${X.name}…`;let D=e.sendGoal(X.name,X.type,{x:L,y:G},A=>{if(P!==D)return;let z=Number(A?.distance_remaining);Ot.feedback.push(z),Ot.feedback.length>500&&Ot.feedback.splice(0,250),ci("feedback"),Number.isFinite(z)&&(l.value=U>0?Math.max(0,Math.min(1,1-z/U)):1,h.textContent=`driving to (${mn(L,2)}, ${mn(G,2)}): ${mn(z,2)} m to go`)});P=D,f.disabled=!1,D.result.then(A=>{if(Ot.lastResult=A,P!==D)return;let z=A.status===4?"reached":A.status===5?"canceled":A.status===6?"aborted":`ended (status ${A.status})`,B=A.values??{};h.textContent=`goal ${z}${B.x!=null?` at (${mn(B.x,2)}, ${mn(B.y,2)})`:""}`,A.status===4&&(l.value=1),f.disabled=!0,P=null},A=>{P===D&&(P=null,f.disabled=!0,A instanceof Hs&&/not allowed/.test(A.message)?Dr(a,"navigate",A.message,c):h.textContent=`goal failed: ${A.message}`)})}f.addEventListener("click",()=>{P?.cancel(),h.textContent+=" · cancel requested"}),p.addEventListener("click",()=>{S=S==="init"?"goal":"init",p.classList.toggle("armed",S==="init")}),r.push(()=>P?.cancel()),(async()=>{let[L,G]=await Promise.all([e.call("/rosapi/action_servers").then(A=>A.action_servers??[],()=>[]),e.call("/rosapi/services").then(A=>A.services??[],()=>[])]),X=L.filter(A=>A.startsWith(o)),y=X.find(A=>/navigate/.test(A))??X[0];if(y){let A=await e.call("/rosapi/service_type",{service:y}).then(z=>String(z.type??""),()=>"");T={name:y,type:A},c.textContent=`Click on the map to send a goal to ${y} (${A}).`}else{let A=await e.advertise(`${o}goal_pose`,"geometry_msgs/msg/PoseStamped");A?Dr(f,"navigate",`the hub lists no navigation action you may use on ${t}, and refused the goal topic: ${A}`,c):(_=!0,r.push(()=>e.unadvertise(`${o}goal_pose`)),c.textContent=`No navigation action listed for you; clicks publish a PoseStamped on ${o}goal_pose.`)}let U=await e.advertise(`${o}initialpose`,"geometry_msgs/msg/PoseWithCovarianceStamped");U?Dr(p,"initialpose",U,g):(R=!0,r.push(()=>e.unadvertise(`${o}initialpose`)));let D=G.filter(A=>A.startsWith(o));if(D.length===0){Dr(d,"services",`the hub lists no services of ${t} you may call (/rosapi/services)`,C);return}for(let A of D)d.appendChild(new Option(A,A));C.textContent="",d.addEventListener("change",()=>O(d.value)),O(D[0])})();async function O(L){m.replaceChildren(ye("p","muted","loading the request type…")),v.replaceChildren();let G="",X=[];try{G=String((await e.call("/rosapi/service_type",{service:L})).type),X=(await e.call("/rosapi/service_request_details",{type:G})).typedefs??[]}catch(z){m.replaceChildren(ye("p","why",`cannot read the type of ${L}: ${z.message}`));return}let y=xp(X);m.replaceChildren(ye("div","muted",`${G} request`));let U=[],D=(z,B,H)=>{B&&B.fieldnames.forEach(($,ne)=>{let oe=B.fieldtypes[ne],se=X.find(Ee=>Ee.type===oe);if(se&&B.fieldarraylen[ne]===-1)return D(z[$],se,[...H,$]);let _e=ye("label","",`${[...H,$].join(".")} (${oe}${B.fieldarraylen[ne]>=0?"[]":""})`),me=ye("input");me.name=[...H,$].join("."),oe==="bool"&&B.fieldarraylen[ne]===-1?me.type="checkbox":me.value=JSON.stringify(z[$]),_e.appendChild(me),m.appendChild(_e),U.push({path:[...H,$],input:me,kind:oe==="bool"&&B.fieldarraylen[ne]===-1?"bool":oe==="string"&&B.fieldarraylen[ne]===-1?"string":"json"})})};D(y,X[0],[]),U.length===0&&m.appendChild(ye("p","muted","(no request fields)"));for(let z of U)z.kind==="string"&&(z.input.value="");let A=Gs("Call","primary");A.type="submit",m.appendChild(A),m.onsubmit=async z=>{z.preventDefault();let B=structuredClone(y);try{for(let H of U){let $=B;for(let oe of H.path.slice(0,-1))$=$[oe];let ne=H.path[H.path.length-1];$[ne]=H.kind==="bool"?H.input.checked:H.kind==="string"?H.input.value:JSON.parse(H.input.value||"null")}}catch(H){v.replaceChildren(ye("p","why",`bad value: ${H.message}`));return}A.disabled=!0,v.replaceChildren(ye("p","muted",`calling ${L}…`));try{let H=await e.call(L,B,10);Ot.lastServiceResponse={service:L,ok:!0,values:H},ci("service-response"),v.replaceChildren(ye("div","ok","response:"),na(H))}catch(H){Ot.lastServiceResponse={service:L,ok:!1,error:H.message},v.replaceChildren(ye("p","why",`refused or failed: ${H.message}`)),H instanceof Hs&&/not allowed/.test(H.message)&&Dr(A,`call:${L}`,H.message,C)}finally{Ot.disabled[`call:${L}`]||(A.disabled=!1)}}}}function cr(n,e,t=""){let i=ye("section",`panel ${t}`),s=ye("h2","",e),r=ye("span","info");s.appendChild(r);let o=ye("div","body");return i.append(s,o),n.appendChild(i),{box:i,body:o,info:r}}var Td=class{n=0;lastLatency=NaN;note(e){this.n++;let t=yl(e?.header);t!=null&&(this.lastLatency=Date.now()-t)}};function Y0(n,e,t){n.innerHTML="";let i=[],s=new Map,r=G=>{let X=s.get(G);return X||s.set(G,X=new Td),X},o=ye("div","robot-title");o.append(ye("a","back","← fleet"),ye("h1","",t),ye("span","badge","…")),o.firstChild.href="#/",n.appendChild(o);let a=o.lastChild,c=ye("div","robot-grid");n.appendChild(c);let l=cr(c,"Map (odometry path, scan, goal)","wide"),h=new Jr(l.body);h.selected=t,h.canvas.id="robot-map",Ot.mapToScreen=(G,X)=>h.toScreen(G,X),i.push(()=>h.destroy(),()=>Ot.mapToScreen=null);let f=cr(c,"Tasking","tasking"),u=cr(c,"Laser scan"),p=cr(c,"Point cloud (3D)"),g=cr(c,"Camera"),b=cr(c,"Topics","full"),d=cr(c,"Inspector","inspector"),m=cr(c,"Link quality (last 5 minutes)","wide"),v=null,C=!1;function S(G){C=!0;let X=G.filter(Ie=>Ie.name.startsWith(`/${t}/`)),y=Ie=>X.filter(Ue=>Ue.type===Ie),U="#2f80ed",D=vu(t,G),A=y("nav_msgs/msg/Odometry")[0];for(let Ie of[D,A&&{topic:A.name,type:A.type}])Ie&&i.push(e.subscribe(Ie.topic,Ue=>{if(r(Ie.topic).note(Ue),Ie.topic===A?.name&&ci("odom"),Ie.topic!==D?.topic)return;let Ve=vl(Ue);Ve&&(v=Ve,h.setPose(t,Ve,U),Ot.poses[t]={...Ve,at:Date.now()},ci("pose"))},{type:Ie.type,throttle_rate:50,queue_length:1,compression:"none"}));D?l.info.textContent=D.topic:l.info.textContent="no pose or odometry topic";let z=y("sensor_msgs/msg/LaserScan")[0];if(z){let Ie=ye("canvas","scan");u.body.appendChild(Ie);let Ue=null,Ve=10,yt=!1;i.push(e.subscribe(z.name,ct=>{if(r(z.name).note(ct),Ue=mp(ct),Ve=ct.range_max||Ve,yt=!0,ci("scan"),v){let It=Math.cos(v.yaw),je=Math.sin(v.yaw),dt=new Float32Array(Ue.length);for(let mt=0;mt<Ue.length;mt+=2)dt[mt]=v.x+It*Ue[mt]-je*Ue[mt+1],dt[mt+1]=v.y+je*Ue[mt]+It*Ue[mt+1];h.scan=dt,h.invalidate()}},{type:z.type,queue_length:1}));let Pt=0,zt=()=>{if(Pt=requestAnimationFrame(zt),!yt||!Ue)return;yt=!1;let ct=devicePixelRatio||1,It=Ie.clientWidth,je=Ie.clientHeight;Ie.width=It*ct,Ie.height=je*ct;let dt=Ie.getContext("2d");dt.setTransform(ct,0,0,ct,0,0),dt.fillStyle="#0b1016",dt.fillRect(0,0,It,je);let mt=Math.min(It,je)/2/Math.min(Ve,15);dt.strokeStyle="#1f2a35";for(let bt=2;bt<=14;bt+=2)dt.beginPath(),dt.arc(It/2,je/2,bt*mt,0,7),dt.stroke();dt.fillStyle="#f2c94c";for(let bt=0;bt<Ue.length;bt+=2)dt.fillRect(It/2-Ue[bt+1]*mt-1,je/2-Ue[bt]*mt-1,2,2);dt.fillStyle="#2f80ed",dt.beginPath(),dt.moveTo(It/2,je/2-10),dt.lineTo(It/2-6,je/2+6),dt.lineTo(It/2+6,je/2+6),dt.fill(),u.info.textContent=`${z.name} · ${Ue.length/2} points · 2 m rings`};Pt=requestAnimationFrame(zt),i.push(()=>cancelAnimationFrame(Pt))}else u.body.appendChild(ye("p","muted","This robot publishes no LaserScan."));let B=y("sensor_msgs/msg/PointCloud2")[0];if(B){let Ie=new Bh(p.body),Ue=ye("select");for(let Ve of["height","intensity"])Ue.appendChild(new Option(`colour by ${Ve}`,Ve));Ue.addEventListener("change",()=>Ie.colourBy=Ue.value),p.box.querySelector("h2").appendChild(Ue),Ie.onShown=Ve=>{Ve!=null&&Ot.cloudAgesMs.push(Date.now()-Ve),Ot.cloudAgesMs.length>2e3&&Ot.cloudAgesMs.splice(0,1e3),ci("cloud-rendered")},i.push(e.subscribe(B.name,Ve=>{r(B.name).note(Ve);let yt=Ie.show(Ve);ci("cloud"),p.info.textContent=`${B.name} · ${yt.toLocaleString()} points`},{type:B.type,queue_length:1})),i.push(()=>Ie.destroy())}else p.body.appendChild(ye("p","muted","This robot publishes no PointCloud2."));let H=y("sensor_msgs/msg/CompressedImage")[0];if(H){let Ie=ye("img","camera"),Ue=ye("canvas","camera bytes"),Ve=ye("p","muted");g.body.append(Ie,Ue,Ve);let yt="",Pt=!1;i.push(e.subscribe(H.name,async zt=>{if(r(H.name).note(zt),ci("camera"),Pt)return;Pt=!0;let ct=yu(zt.data),It=_p(ct);try{let je=new Blob([ct],{type:`image/${It==="png"?"png":"jpeg"}`});(await createImageBitmap(je)).close(),yt&&URL.revokeObjectURL(yt),yt=URL.createObjectURL(je),Ie.src=yt,Ie.style.display="",Ue.style.display="none",Ve.textContent="",g.info.textContent=`${H.name} · ${zt.format} · ${(ct.length/1024).toFixed(0)} KiB`}catch{Ie.style.display="none",Ue.style.display="";let je=Math.max(1,Math.floor(Math.sqrt(ct.length)));Ue.width=je,Ue.height=je;let dt=Ue.getContext("2d"),mt=dt.createImageData(je,je);for(let bt=0;bt<je*je;bt++){let k=ct[bt];mt.data[bt*4]=mt.data[bt*4+1]=mt.data[bt*4+2]=k,mt.data[bt*4+3]=255}dt.putImageData(mt,0,0),Ve.textContent=`not a decodable ${zt.format} image (${It==="unknown"?"no image header":`${It} header, undecodable body`}): showing its ${ct.length.toLocaleString()} bytes as grey levels`,g.info.textContent=`${H.name} · ${zt.format} · ${(ct.length/1024).toFixed(0)} KiB`}finally{Pt=!1}},{type:H.type,queue_length:1})),i.push(()=>yt&&URL.revokeObjectURL(yt))}else g.body.appendChild(ye("p","muted","This robot publishes no CompressedImage."));let $=ye("select"),ne=ye("div","tree");d.body.append($,ne);let oe=new Set([z?.name,B?.name,H?.name,D?.topic]),se=X.find(Ie=>!oe.has(Ie.name)&&Ie.rate_hz>0)??X.find(Ie=>!oe.has(Ie.name))??X[0];for(let Ie of X)$.appendChild(new Option(`${Ie.name} (${Ie.type})`,Ie.name));se&&($.value=se.name);let _e=null,me=null,Ee=0,Se=0,Ze=performance.now(),rt=()=>{_e?.();let Ie=X.find(Ue=>Ue.name===$.value);Ie&&(Se=0,Ze=performance.now(),me=null,ne.textContent="waiting for a message…",_e=e.subscribe(Ie.name,(Ue,Ve,yt)=>{r(Ie.name).note(Ue),me=Ue,Ee=yt,Se++,ci("inspector")},{type:Ie.type,queue_length:1,throttle_rate:200}))};$.addEventListener("change",rt),rt();let Ye=window.setInterval(()=>{if(!me)return;let Ie=Se/((performance.now()-Ze)/1e3),Ue=r($.value).lastLatency;d.info.textContent=`${mn(Ie)} msg/s shown · latency ${mn(Ue,0)} ms · ${Math.round(performance.now()-Ee)} ms ago`,ne.replaceChildren(na(xl(me),$.value))},1e3);i.push(()=>{clearInterval(Ye),_e?.()}),q0(f.body,e,t,h,()=>v,i)}let P=ye("table","topics");P.innerHTML="<thead><tr><th>topic</th><th>type</th><th>rate (hub)</th><th>bandwidth (hub)</th><th>latency (here)</th><th>drops</th></tr></thead>";let T=ye("tbody");P.appendChild(T),b.body.appendChild(P);let _=new Map,R=new Sr(3,300),W=new Fl(m.body,R,[{label:"RTT ms",colour:"#f2994a",scale:"ms"},{label:"latency ms",colour:"#eb5757",scale:"ms"},{label:"link MB/s",colour:"#27ae60",scale:"r"}],Math.max(400,m.body.clientWidth||900),180);i.push(()=>W.destroy());async function O(){let G,X;try{[{robots:G},{topics:X}]=await Promise.all([Ti("/api/v1/robots"),Ti("/api/v1/topics")])}catch(D){a.textContent=`cannot read the hub: ${D.message}`;return}let y=G.find(D=>D.name===t);a.textContent=y?y.online?"online":"offline":"not visible to you",a.className=`badge ${y?.online?"ok":"off"}`,n.classList.toggle("offline",!!y&&!y.online),!C&&y?.online&&S(X);let U=Date.now()/1e3;y?.online&&R.push(U,y.rtt_ms??null,y.latency_ms??null,y.link_rate_bps!=null?y.link_rate_bps/1e6:null),W.update();for(let D of X.filter(A=>A.name.startsWith(`/${t}/`))){let A=_.get(D.name);if(!A){let H=ye("tr"),$=Array.from({length:6},()=>ye("td"));$[0].textContent=D.name,$[1].textContent=D.type,H.append(...$),T.appendChild(H);let ne=[new Sr(1,120),new Sr(1,120),new Sr(1,120)];A={rate:new ao($[2],ne[0],"#2f80ed"),bw:new ao($[3],ne[1],"#27ae60"),lat:new ao($[4],ne[2],"#eb5757"),s:ne,drops:$[5]},_.set(D.name,A)}let z=s.get(D.name)?.lastLatency??NaN;A.s[0].push(U,D.rate_hz),A.s[1].push(U,D.bandwidth_bps),A.s[2].push(U,Number.isFinite(z)?z:null),A.rate.update(`${mn(D.rate_hz)} Hz`),A.bw.update(Zr(D.bandwidth_bps)),A.lat.update(Number.isFinite(z)?`${mn(z,0)} ms`:"not subscribed");let B=Object.entries(D.drops??{}).filter(([,H])=>H);A.drops.textContent=B.length?B.map(([H,$])=>`${H} ${$}`).join(", "):"0"}}O();let L=window.setInterval(O,1e3);return i.push(()=>clearInterval(L),()=>_.forEach(G=>{G.rate.destroy(),G.bw.destroy(),G.lat.destroy()})),()=>i.forEach(G=>G())}var $i=n=>document.getElementById(n),kh=$i("main"),$0=$i("conn"),DE=$i("who"),Z0=$i("signin"),J0=$i("signout"),Ad=$i("estop"),Rd=$i("estop-note"),Cd=$i("login");function K0(){try{let n=JSON.parse(localStorage.getItem("fleetlink.estop")??"null");if(n?.topic&&n?.type)return n}catch{}return{topic:"/fleet/estop",type:"std_msgs/msg/Bool"}}var hr,zh=()=>{};function Pd(){hr?.close(),hr=new gl(ys.wsUrl()),globalThis.fleetlinkRosbridge=hr,hr.onState=(e,t)=>{$0.textContent=e==="open"?"connected":e==="connecting"?"connecting…":`disconnected (${t}), retrying`,$0.className=`conn ${e}`,e==="open"&&NE()};let n=ys.principal();DE.textContent=n==="token"?"signed in with a token":n?`signed in as ${n}`:"anonymous (read-only where the hub allows)",Z0.hidden=!!n,J0.hidden=!n}async function NE(){let n=K0(),e=await hr.advertise(n.topic,n.type);Ad.disabled=!!e,Ad.title=e?`Disabled: ${e}`:`publishes ${n.type} {data: true} on ${n.topic}`,Rd.textContent=e?`e-stop disabled: ${e}`:`→ ${n.topic}`,e?Ot.disabled.estop=e:delete Ot.disabled.estop}Ad.addEventListener("click",()=>{let n=K0(),e=n.type.endsWith("/Bool")?{data:!0}:{};for(let t=0;t<3;t++)setTimeout(()=>hr.publish(n.topic,e,i=>Rd.textContent=`e-stop refused: ${i}`),t*100);Rd.textContent=`e-stop sent on ${n.topic} at ${new Date().toLocaleTimeString()}`});function Vh(){zh();let n=location.hash.replace(/^#\/?/,"");document.querySelectorAll("nav a").forEach(e=>e.classList.toggle("active",e.hash===`#/${n.split("/")[0]}`)),kh.classList.remove("offline"),n.startsWith("robot/")?zh=Y0(kh,hr,decodeURIComponent(n.slice(6))):n==="admin"?zh=dp(kh):zh=Sp(kh,hr,e=>location.hash=`#/robot/${encodeURIComponent(e)}`)}Z0.addEventListener("click",()=>Cd.showModal());$i("login-cancel").addEventListener("click",()=>Cd.close());$i("login-form").addEventListener("submit",async n=>{n.preventDefault();let e=n.target,t=e.elements.namedItem("user").value,i=e.elements.namedItem("password").value,s=e.elements.namedItem("token").value.trim(),r=$i("login-error");r.textContent="";try{if(s){let o=await fetch("/api/v1/robots",{headers:{Authorization:`Bearer ${s}`}});if(!o.ok)throw new $o(o.status,(await o.json().catch(()=>null))?.error??`HTTP ${o.status}`);ys.set(s,"token")}else{let o=await Ti("/api/v1/login",{method:"POST",body:JSON.stringify({user:t,password:i})});ys.set(o.token,o.principal)}e.reset(),Cd.close(),Pd(),Vh()}catch(o){r.textContent=`sign-in refused: ${o.message}`}});J0.addEventListener("click",async()=>{ys.principal()!=="token"&&await Ti("/api/v1/logout",{method:"POST"}).catch(()=>{}),ys.clear(),Pd(),Vh()});window.addEventListener("hashchange",Vh);Pd();Vh();var j0=()=>{Ot.renders++,requestAnimationFrame(j0)};requestAnimationFrame(j0);
